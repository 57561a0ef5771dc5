// Which surfaces show in the current view, counted in pixels (for the tests,
// doc/viewer.md): the view is rendered offscreen with every surface in its
// own flat colour. Solid surfaces (and the fine triangles) hide what is
// behind them; a see-through side hides nothing, so each see-through surface
// and the path are rendered alone over the solid ones' depth.
import * as THREE from 'three';

function idColour(index) {
  const n = index + 1;  // 0 is the background
  return new THREE.Color().setRGB((n & 255) / 255, ((n >> 8) & 255) / 255, ((n >> 16) & 255) / 255,
                                  THREE.LinearSRGBColorSpace);
}

/** The render target's pixels, with their size. */
function readPixels(renderer, target) {
  const data = new Uint8Array(target.width * target.height * 4);
  renderer.readRenderTargetPixels(target, 0, 0, target.width, target.height, data);
  return {data, width: target.width, height: target.height};
}

/** The id (index) drawn at pixel i (4 bytes per pixel), -1 for the background. */
const idAt = (data, i) => (data[i] | (data[i + 1] << 8) | (data[i + 2] << 16)) - 1;

/**
 * Per id in `pixels` (or, with `anyId`, every drawn pixel as id 0): its pixel
 * count and the pixel nearest the mean of its pixels, in CSS pixels of a
 * canvas `cssWidth` x `cssHeight` (a point to click on).
 */
function tally(pixels, cssWidth, cssHeight, anyId = false) {
  const {data, width, height} = pixels;
  const stats = new Map();
  const idOf = (i) => (anyId ? (idAt(data, i) >= 0 ? 0 : -1) : idAt(data, i));
  for (let i = 0; i < data.length; i += 4) {
    const id = idOf(i);
    if (id < 0) continue;
    const s = stats.get(id) ?? {count: 0, sx: 0, sy: 0, best: Infinity, at: null};
    s.count += 1;
    s.sx += (i / 4) % width;
    s.sy += Math.floor(i / 4 / width);
    stats.set(id, s);
  }
  for (let i = 0; i < data.length; i += 4) {
    const s = stats.get(idOf(i));
    if (!s) continue;
    const x = (i / 4) % width, y = Math.floor(i / 4 / width);
    const d = (x - s.sx / s.count) ** 2 + (y - s.sy / s.count) ** 2;
    if (d < s.best) {
      s.best = d;
      s.at = [(x + 0.5) * cssWidth / width, (height - y - 0.5) * cssHeight / height];
    }
  }
  return stats;
}

/** Sets `visible` and `material` of objects, remembering them for restore(). */
class SceneOverride {
  constructor() { this.saved = new Map(); }
  set(object, visible, material) {
    if (!this.saved.has(object)) {
      this.saved.set(object, {visible: object.visible, material: object.material});
    }
    object.visible = visible;
    if (material) object.material = material;
  }
  restore() {
    for (const [object, {visible, material}] of this.saved) {
      object.visible = visible;
      object.material = material;
    }
  }
}

/**
 * Renders the view offscreen at `scale` of the canvas and returns {width,
 * height, surfaces: [{id, kind, seeThrough, pixels, at}], pathPixels}; `at`
 * is a point of the canvas (CSS pixels) where the surface shows, null if
 * nowhere. `surfaces` is collectSurfaces(...) after update(camera);
 * `overlay` the scene of the path (drawn after `scene`). Hidden surfaces
 * (ceilings toggled off) count 0. With `alone`, each surface (and the path)
 * is rendered with nothing in front of it.
 */
export function surfacePixels(renderer, scene, camera, surfaces, overlay,
                              {scale = 0.5, alone = false} = {}) {
  const size = renderer.getSize(new THREE.Vector2());
  const target = new THREE.WebGLRenderTarget(Math.max(1, Math.round(size.x * scale)),
                                             Math.max(1, Math.round(size.y * scale)));
  const shown = surfaces.list.filter((s) => s.meshes[0].visible);
  const solid = alone ? [] : shown.filter((s) => !s.seeThrough);
  const renderables = [];
  scene.traverse((o) => { if (o.isMesh || o.isLine || o.isPoints) renderables.push(o); });
  let pathShown = false;
  overlay.traverse((o) => { pathShown ||= (o.isMesh || o.isLine) && o.visible && isShown(o); });
  const occluder = new THREE.MeshBasicMaterial({color: 0x000000, side: THREE.DoubleSide});
  const idMaterials = new Map(solid.map((s, index) => [s, new THREE.MeshBasicMaterial(
      {color: idColour(index), side: THREE.DoubleSide})]));

  // The solid surfaces in their colours, the fine triangles black.
  const override = new SceneOverride();
  for (const object of renderables) {
    const surface = surfaces.byMesh.get(object);
    if (surface) override.set(object, idMaterials.has(surface), idMaterials.get(surface) ?? null);
    else if (object.isMesh && object.visible) {
      override.set(object, true, occluder);
    } else override.set(object, false, null);
  }
  const saved = {background: scene.background, autoClear: renderer.autoClear,
                 clearColor: renderer.getClearColor(new THREE.Color()),
                 clearAlpha: renderer.getClearAlpha()};
  scene.background = null;
  renderer.setClearColor(0x000000, 0);
  renderer.setRenderTarget(target);
  renderer.clear();
  renderer.render(scene, camera);
  const counts = tally(readPixels(renderer, target), size.x, size.y);
  const pixels = new Map(solid.map((s, index) => [s, counts.get(index)]));

  // Each see-through surface (alone: each surface), then the path, over the solid depth.
  const white = new THREE.MeshBasicMaterial({color: 0xffffff, side: THREE.DoubleSide,
                                             depthWrite: false});
  const overlays = shown.filter((s) => alone || s.seeThrough).map((s) => [s, s.meshes]);
  if (pathShown) overlays.push(['path', []]);
  renderer.autoClear = false;
  for (const [key, objects] of overlays) {
    for (const object of renderables) object.visible = objects.includes(object);
    for (const object of objects) object.material = white;
    if (alone) renderer.clear();
    else renderer.clearColor();
    renderer.render(key === 'path' ? overlay : scene, camera);
    pixels.set(key, tally(readPixels(renderer, target), size.x, size.y, true).get(0));
  }
  override.restore();
  renderer.autoClear = saved.autoClear;
  renderer.setClearColor(saved.clearColor, saved.clearAlpha);
  renderer.setRenderTarget(null);
  scene.background = saved.background;
  target.dispose();
  return {
    width: target.width,
    height: target.height,
    surfaces: surfaces.list.map((s) => ({id: s.id, kind: s.kind, seeThrough: s.seeThrough,
                                         pixels: pixels.get(s)?.count ?? 0,
                                         at: pixels.get(s)?.at ?? null})),
    pathPixels: pixels.get('path')?.count ?? 0,
  };
}

/** `object` and all its parents visible. */
function isShown(object) {
  for (let o = object; o; o = o.parent) if (!o.visible) return false;
  return true;
}
