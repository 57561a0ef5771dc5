// The map's rectangles as surfaces the viewer can show, hide, see through and
// inspect (doc/viewer.md). planar-mapper's GLB has one node per rectangle
// tile, "surface_<id>_<tile>", with extras {surface_id, tile, support}; the
// tiles of one surface are grouped. Every surface is drawn double-sided; the
// side the robot did not see (against the normal, which map.glb turns towards
// the robot) is drawn see-through while it faces the camera, so the near
// walls and the ceiling do not hide the rooms behind them.
import * as THREE from 'three';

const SURFACE_NAME = /^surface_(\d+)_(\d+)$/;
const SEE_THROUGH_OPACITY = 0.3;
const HIGHLIGHT = new THREE.Color(0x2f6bff);

function surfaceIdOf(object) {
  if (!object.isMesh) return null;
  const id = object.userData.surface_id;
  if (Number.isInteger(id) && id >= 0) return id;
  const match = SURFACE_NAME.exec(object.userData.name ?? object.name);
  return match ? Number(match[1]) : null;
}

/** World positions of a mesh's vertices. */
function worldVertices(mesh) {
  const position = mesh.geometry.attributes.position;
  const vertices = [];
  for (let i = 0; i < position.count; ++i) {
    vertices.push(new THREE.Vector3().fromBufferAttribute(position, i).applyMatrix4(mesh.matrixWorld));
  }
  return vertices;
}

/** The mesh's normal in the world: its NORMAL attribute, else its first triangle's winding. */
function worldNormal(mesh, vertices) {
  const normals = mesh.geometry.attributes.normal;
  if (normals) {
    const matrix = new THREE.Matrix3().getNormalMatrix(mesh.matrixWorld);
    return new THREE.Vector3().fromBufferAttribute(normals, 0).applyMatrix3(matrix).normalize();
  }
  const index = mesh.geometry.index;
  const [a, b, c] = [0, 1, 2].map((k) => vertices[index ? index.getX(k) : k]);
  return new THREE.Vector3().subVectors(b, a).cross(new THREE.Vector3().subVectors(c, a)).normalize();
}

/** Min and max of the vertices along `axis`. */
function extent(vertices, axis) {
  let lo = Infinity, hi = -Infinity;
  for (const v of vertices) {
    const d = v.dot(axis);
    lo = Math.min(lo, d);
    hi = Math.max(hi, d);
  }
  return [lo, hi];
}

/**
 * Size and centre of a surface from its tiles' vertices: "width" runs along
 * the more horizontal of the rectangle's two edge directions, "height" along
 * the other (a wall's height is vertical).
 */
function measure(vertices, normal) {
  let along = new THREE.Vector3().subVectors(vertices[1], vertices[0]);
  along.addScaledVector(normal, -along.dot(normal)).normalize();
  let up = new THREE.Vector3().crossVectors(normal, along).normalize();
  if (Math.abs(up.z) < Math.abs(along.z)) [along, up] = [up, along];
  const [u0, u1] = extent(vertices, along), [v0, v1] = extent(vertices, up);
  const centre = new THREE.Vector3()
      .addScaledVector(along, (u0 + u1) / 2)
      .addScaledVector(up, (v0 + v1) / 2)
      .addScaledVector(normal, vertices[0].dot(normal));
  return {width: u1 - u0, height: v1 - v0, centre};
}

/**
 * wall, floor, ceiling or slanted. A horizontal surface above the middle of
 * the map's height is a ceiling, below it a floor (the robot's path, which
 * orients the normals, runs at floor height, so a floor's normal may point
 * either way).
 */
function kindOf(normal, centre, mapBox) {
  if (Math.abs(normal.z) > 0.9) {
    return centre.z > (mapBox.min.z + mapBox.max.z) / 2 ? 'ceiling' : 'floor';
  }
  return Math.abs(normal.z) < 0.2 ? 'wall' : 'slanted';
}

/** Side the robot saw: map.glb's normal; up for floors and down for ceilings. */
function innerNormal(kind, normal) {
  if (kind === 'floor') return new THREE.Vector3(0, 0, 1);
  if (kind === 'ceiling') return new THREE.Vector3(0, 0, -1);
  return normal.clone();
}

/** Per mesh: a solid double-sided material and a see-through one (own copies: highlighting). */
function prepareMaterials(mesh) {
  const solid = mesh.material.clone();
  solid.side = THREE.DoubleSide;
  const seeThrough = solid.clone();
  seeThrough.transparent = true;
  seeThrough.opacity = SEE_THROUGH_OPACITY;
  seeThrough.depthWrite = false;
  seeThrough.forceSinglePass = true;  // a flat quad: no back-then-front passes needed
  mesh.userData.pmapMaterials = {solid, seeThrough};
  mesh.material = solid;
}

function makeSurface(id, meshes, mapBox) {
  const vertices = meshes.flatMap(worldVertices);
  const normal = worldNormal(meshes[0], vertices);
  const {width, height, centre} = measure(vertices, normal);
  const kind = kindOf(normal, centre, mapBox);
  const supports = meshes.map((m) => m.userData.support).filter(Number.isInteger);
  meshes.forEach(prepareMaterials);
  return {
    id, kind, meshes, normal, centre, width, height,
    inner: innerNormal(kind, normal),
    support: supports.length ? supports[0] : null,
    seeThrough: false,
  };
}

/** Round to `digits` decimals (for the page's JSON). */
const round = (x, digits = 3) => Number(x.toFixed(digits)) || 0;  // no -0

/** What the inspector shows of a surface (plain data). */
export function surfaceInfo(surface) {
  return {
    id: surface.id,
    kind: surface.kind,
    tiles: surface.meshes.length,
    width_m: round(surface.width),
    height_m: round(surface.height),
    area_m2: round(surface.width * surface.height),
    normal: surface.normal.toArray().map((x) => round(x)),
    centre: surface.centre.toArray().map((x) => round(x)),
    support: surface.support,
  };
}

/**
 * The surfaces of `model` (its matrices up to date), by id. Meshes that are
 * not surfaces (fine triangles, another exporter's meshes) are drawn
 * double-sided too. Returns {list, byMesh, update(camera), setCeilingsVisible(v),
 * setSeeThrough(v), highlight(id)}.
 */
export function collectSurfaces(model, mapBox) {
  const groups = new Map();
  model.traverse((object) => {
    const id = surfaceIdOf(object);
    if (id !== null) {
      if (!groups.has(id)) groups.set(id, []);
      groups.get(id).push(object);
    } else if (object.isMesh) {
      for (const material of [object.material].flat()) material.side = THREE.DoubleSide;
    }
  });
  const list = [...groups.entries()].sort((a, b) => a[0] - b[0])
      .map(([id, meshes]) => makeSurface(id, meshes, mapBox));
  const byMesh = new Map(list.flatMap((s) => s.meshes.map((m) => [m, s])));
  const state = {ceilings: true, seeThrough: true};
  const toCamera = new THREE.Vector3();
  return {
    list,
    byMesh,
    /** Chooses each surface's material for the camera's position (call before rendering). */
    update(camera) {
      for (const s of list) {
        const outer = s.inner.dot(toCamera.subVectors(camera.position, s.centre)) < 0;
        s.seeThrough = state.seeThrough && outer;
        for (const mesh of s.meshes) {
          const {solid, seeThrough} = mesh.userData.pmapMaterials;
          mesh.material = s.seeThrough ? seeThrough : solid;
          mesh.visible = state.ceilings || s.kind !== 'ceiling';
        }
      }
    },
    setCeilingsVisible(visible) { state.ceilings = visible; },
    setSeeThrough(enabled) { state.seeThrough = enabled; },
    get ceilingsVisible() { return state.ceilings; },
    get seeThroughEnabled() { return state.seeThrough; },
    /** Tints the surface `id` (null: none). */
    highlight(id) {
      for (const s of list) {
        for (const mesh of s.meshes) {
          for (const material of Object.values(mesh.userData.pmapMaterials)) {
            if (!material.emissive) continue;
            material.emissive.copy(s.id === id ? HIGHLIGHT : new THREE.Color(0));
            material.emissiveIntensity = s.id === id ? 0.6 : 1;
          }
        }
      }
    },
  };
}
