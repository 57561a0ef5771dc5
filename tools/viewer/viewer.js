// planar-mapper's map viewer (doc/viewer.md). Bundled with three.js into one
// classic IIFE script at build time (libs/viewer/CMakeLists.txt) and inlined
// in viewer.html together with the model (GLB) and the raw points, so the
// page works from file:// with no network.
//
// World frame: the mapper's, metres, z up (camera.up = +z). The GLB follows
// glTF (y up; the exporter's root node turns z up into y up), so the loaded
// scene is turned back by +90 degrees about x; the raw points are z up as is.
import * as THREE from 'three';
import {GLTFLoader} from 'three/addons/loaders/GLTFLoader.js';
import {OrbitControls} from 'three/addons/controls/OrbitControls.js';
import {boxInView, frameBox, viewDirection} from './camera_fit.js';
import {readEmbeddedData} from './embedded_data.js';
import {createHud, formatValue} from './hud.js';
import {createInspector} from './inspector.js';
import {collectSurfaces, surfaceInfo} from './map_surfaces.js';
import {extractRobotPath} from './robot_path.js';
import {surfacePixels} from './visibility.js';

const BACKGROUND = 0xeef1f4;

/**
 * A GLTFLoader plugin that decodes the map's texture images through <img>
 * elements instead of createImageBitmap. An image element's load delays the
 * page's load event and holds Chromium's virtual time, so the first frame is
 * drawn before a headless `chromium --screenshot --virtual-time-budget=...`
 * (doc/viewer.md) takes its picture; an ImageBitmap decodes off the main
 * thread, unseen by both, and on a loaded machine that command captured the
 * page before its first frame (a blank canvas and an empty HUD).
 */
function mainThreadImages(parser) {
  parser.textureLoader = new THREE.TextureLoader(parser.options.manager);
  return {name: 'pmap_main_thread_images'};
}

function parseGlb(glb) {
  const loader = new GLTFLoader();
  loader.register(mainThreadImages);
  return new Promise((resolve, reject) => loader.parse(glb, '', resolve, reject));
}

/** The glTF scene (y up) under a group that turns it back to z up. */
function zUpModel(gltf) {
  const group = new THREE.Group();
  group.name = 'map';
  group.rotation.x = Math.PI / 2;
  group.add(gltf.scene);
  return group;
}

function countTriangles(object) {
  let triangles = 0;
  object.traverse((node) => {
    if (!node.isMesh) return;
    const geometry = node.geometry;
    const count = geometry.index ? geometry.index.count : geometry.attributes.position.count;
    triangles += Math.floor(count / 3);
  });
  return triangles;
}

/** Raw points coloured by height (blue low, red high), hidden at first. */
function rawPoints(positions) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.computeBoundingBox();
  const {min, max} = geometry.boundingBox;
  const span = Math.max(max.z - min.z, 1e-6);
  const colors = new Float32Array(positions.length);
  const color = new THREE.Color();
  for (let i = 0; i < positions.length; i += 3) {
    color.setHSL(0.66 * (1 - (positions[i + 2] - min.z) / span), 0.8, 0.45);
    colors.set([color.r, color.g, color.b], i);
  }
  geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
  const material = new THREE.PointsMaterial({size: 2, sizeAttenuation: false, vertexColors: true});
  const points = new THREE.Points(geometry, material);
  points.name = 'raw points';
  points.visible = false;
  return points;
}

function addLights(scene) {
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8d8d8d, 2.0));
  const sun = new THREE.DirectionalLight(0xffffff, 1.5);
  sun.position.set(0.4, -0.6, 1.0);
  scene.add(sun);
}

/** Bounding box of what is drawn: the map, else the points, else a unit cube. */
function sceneBox(model, points) {
  const box = new THREE.Box3();
  if (model) box.setFromObject(model);
  if (box.isEmpty() && points) box.setFromObject(points, true);
  if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
  return box;
}

/** A grid on the floor of `box` (in the x-y plane). */
function floorGrid(box) {
  const size = box.getSize(new THREE.Vector3());
  const extent = Math.max(size.x, size.y, 1);
  const cells = Math.min(200, Math.ceil(extent));
  const grid = new THREE.GridHelper(cells, cells, 0xb0b6bd, 0xd5d9de);
  grid.rotation.x = Math.PI / 2;
  const center = box.getCenter(new THREE.Vector3());
  grid.position.set(Math.round(center.x), Math.round(center.y), box.min.z - 0.01);
  return grid;
}

function createRenderer() {
  const renderer = new THREE.WebGLRenderer({antialias: true});
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setSize(window.innerWidth, window.innerHeight);
  renderer.domElement.id = 'pmap-canvas';
  document.body.appendChild(renderer.domElement);
  return renderer;
}

/** The HUD's controls; `view` re-renders and holds what they act on. */
function addControls(hud, data, view) {
  const {points, surfaces, path, inspector, render} = view;
  const ceilings = surfaces.list.filter((s) => s.kind === 'ceiling').length;
  if (path) hud.addLine('robot path', `${formatValue(Math.round(path.lengthM * 10) / 10)} m`);
  hud.addToggle('pmap-points-toggle',
                `raw points (${formatValue(data.points.shown)} of ${formatValue(data.points.total)})`,
                {disabled: data.points.shown === 0}, (visible) => {
                  if (points) points.visible = visible;
                  render();
                });
  hud.addToggle('pmap-ceilings-toggle', `ceilings (${ceilings})`,
                {checked: true, disabled: ceilings === 0}, (visible) => {
                  surfaces.setCeilingsVisible(visible);
                  if (!visible && inspector.selected()?.kind === 'ceiling') inspector.clear();
                  render();
                });
  hud.addToggle('pmap-see-through-toggle', 'see-through outer sides',
                {checked: true, disabled: surfaces.list.length === 0,
                 title: 'draw the side of a surface the robot did not see see-through, ' +
                        'so near walls and the ceiling do not hide the rooms'},
                (enabled) => {
                  surfaces.setSeeThrough(enabled);
                  render();
                });
  hud.addToggle('pmap-path-toggle', 'robot path', {checked: Boolean(path), disabled: !path},
                (visible) => {
                  if (path) path.object.visible = visible;
                  render();
                });
  hud.addButton('pmap-frame-all', 'frame all', 'fit the view to the whole map', view.frameAll);
  hud.addHint('drag: rotate · right-drag: pan · wheel: zoom · click: inspect a surface');
}

/** What the page reports after each frame (window.pmapViewer, doc/viewer.md). */
function viewerState(drawn, view, modelTriangles) {
  const {camera, controls, box, points, surfaces, path, inspector} = view;
  const round = (v) => v.toArray().map((x) => Number(x.toFixed(3)));
  return {
    ready: true,
    triangles: drawn.triangles,
    points: drawn.points,
    modelTriangles,
    pointsVisible: points ? points.visible : false,
    frames: (window.pmapViewer?.frames ?? 0) + 1,
    surfaces: surfaces.list.length,
    ceilingsVisible: surfaces.ceilingsVisible,
    seeThrough: surfaces.seeThroughEnabled,
    path: path ? {visible: path.object.visible, positions: path.positions,
                  length_m: Number(path.lengthM.toFixed(3))} : null,
    selected: inspector.selected(),
    boxInView: boxInView(camera, box),
    box: {min: round(box.min), max: round(box.max)},
    camera: {position: round(camera.position), target: round(controls.target)},
  };
}

/** Hooks for the tests (tools/viewer/probe.js): plain functions, not state. */
function testHooks(renderer, scene, view) {
  return {
    surfaces: () => view.surfaces.list.map(surfaceInfo),
    surfacePixels: (options) => {
      const result = surfacePixels(renderer, scene, view.camera, view.surfaces, view.overlay,
                                   options);
      view.render();
      return result;
    },
  };
}

async function start() {
  const data = readEmbeddedData();
  const renderer = createRenderer();
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(BACKGROUND);
  addLights(scene);
  const model = data.glb ? zUpModel(await parseGlb(data.glb)) : null;
  const points = data.positions.length ? rawPoints(data.positions) : null;
  if (model) scene.add(model);
  if (points) scene.add(points);
  scene.updateMatrixWorld(true);
  const box = sceneBox(model, points);
  scene.add(floorGrid(box));
  const markerRadius = Math.max(0.05, box.getSize(new THREE.Vector3()).length() / 250);
  const path = model ? extractRobotPath(model, markerRadius) : null;
  // The path is drawn in a second pass, over the map's depth, so that
  // `triangles` counts the map's triangles alone.
  const overlay = new THREE.Scene();
  if (path) overlay.add(path.object);
  const surfaces = collectSurfaces(model ?? new THREE.Group(), box);

  const camera = new THREE.PerspectiveCamera(50, window.innerWidth / window.innerHeight, 0.1, 1000);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, renderer.domElement);
  frameBox(camera, controls, box);

  const modelTriangles = model ? countTriangles(model) : 0;
  const view = {camera, controls, box, points, surfaces, path, overlay};
  view.render = () => {
    surfaces.update(camera);
    renderer.render(scene, camera);
    const drawn = {...renderer.info.render};
    renderer.autoClear = false;
    renderer.render(overlay, camera);
    renderer.autoClear = true;
    view.hud?.setTriangles(drawn.triangles);
    window.pmapViewer = viewerState(drawn, view, modelTriangles);
  };
  view.frameAll = () => {
    frameBox(camera, controls, box, viewDirection(camera, controls));
    view.render();
  };
  view.inspector = createInspector(renderer.domElement, camera, surfaces, view.render);
  view.hud = createHud(data.info);
  addControls(view.hud, data, view);
  window.pmapViewerTest = testHooks(renderer, scene, view);
  controls.addEventListener('change', view.render);
  window.addEventListener('resize', () => {
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
    view.render();
  });
  view.render();
}

start().catch((error) => {
  const message = error?.message ?? String(error);
  window.pmapViewer = {ready: false, error: message};
  const line = document.createElement('div');
  line.className = 'pmap-error';
  line.textContent = `viewer error: ${message}`;
  document.getElementById('pmap-hud')?.append(line);
  console.error('pmap viewer:', error);
});
