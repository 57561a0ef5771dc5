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
import {readEmbeddedData} from './embedded_data.js';
import {createHud} from './hud.js';

const BACKGROUND = 0xeef1f4;

function parseGlb(glb) {
  return new Promise((resolve, reject) => new GLTFLoader().parse(glb, '', resolve, reject));
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

/** Puts the camera south-west of and above `box`, looking at its centre. */
function frameBox(camera, controls, box) {
  const center = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 0.5);
  const distance = (0.9 * radius) / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2));
  const direction = new THREE.Vector3(-0.55, -0.75, 0.65).normalize();
  camera.position.copy(center).addScaledVector(direction, distance);
  camera.near = Math.max(distance / 1000, 0.01);
  camera.far = distance * 20;
  camera.updateProjectionMatrix();
  controls.target.copy(center);
  controls.update();
}

function createRenderer() {
  const renderer = new THREE.WebGLRenderer({antialias: true});
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setSize(window.innerWidth, window.innerHeight);
  renderer.domElement.id = 'pmap-canvas';
  document.body.appendChild(renderer.domElement);
  return renderer;
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
  const box = sceneBox(model, points);
  scene.add(floorGrid(box));

  const camera = new THREE.PerspectiveCamera(50, window.innerWidth / window.innerHeight, 0.1, 1000);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, renderer.domElement);
  frameBox(camera, controls, box);

  const modelTriangles = model ? countTriangles(model) : 0;
  const hud = createHud(data.info, data.points, (visible) => {
    if (points) points.visible = visible;
    render();
  });
  const render = () => {
    renderer.render(scene, camera);
    hud.setTriangles(renderer.info.render.triangles);
    window.pmapViewer = {
      ready: true,
      triangles: renderer.info.render.triangles,
      points: renderer.info.render.points,
      modelTriangles,
      pointsVisible: points ? points.visible : false,
      frames: (window.pmapViewer?.frames ?? 0) + 1,
    };
  };
  controls.addEventListener('change', render);
  window.addEventListener('resize', () => {
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
    render();
  });
  render();
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
