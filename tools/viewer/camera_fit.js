// Fitting the camera to the map's bounding box: the initial view and the
// "frame all" button (doc/viewer.md).
import * as THREE from 'three';

/** The initial view: from the south-west and above (world z up). */
export const DEFAULT_DIRECTION = new THREE.Vector3(-0.55, -0.75, 0.65).normalize();

/** How far inside the view's edges (in normalised device coordinates) a fitted box stays. */
const FIT_NDC = 0.92;

function boxCorners(box) {
  const corners = [];
  for (let i = 0; i < 8; ++i) {
    corners.push(new THREE.Vector3(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
                                   i & 4 ? box.max.z : box.min.z));
  }
  return corners;
}

/**
 * True when every corner of `box` is in front of the camera and projects
 * within `limit` of the view's centre (1: the view's edge), i.e. the whole
 * box is in view.
 */
export function boxInView(camera, box, limit = 1) {
  camera.updateMatrixWorld();
  const inCamera = new THREE.Vector3();
  return boxCorners(box).every((corner) => {
    inCamera.copy(corner).applyMatrix4(camera.matrixWorldInverse);
    if (-inCamera.z < camera.near) return false;
    const ndc = corner.clone().project(camera);
    return Math.abs(ndc.x) <= limit && Math.abs(ndc.y) <= limit;
  });
}

/** Distance at which the box's bounding sphere fits the narrower field of view. */
function sphereDistance(camera, radius) {
  const vertical = THREE.MathUtils.degToRad(camera.fov) / 2;
  const horizontal = Math.atan(Math.tan(vertical) * camera.aspect);
  return radius / Math.sin(Math.min(vertical, horizontal));
}

function placeCamera(camera, center, direction, distance) {
  camera.position.copy(center).addScaledVector(direction, distance);
  camera.near = Math.max(distance / 1000, 0.01);
  camera.far = distance * 20;
  camera.lookAt(center);
  camera.updateProjectionMatrix();
}

/**
 * Puts the camera on `direction` (unit, from the box's centre towards the
 * camera) at the smallest distance at which the whole box is in view with a
 * margin, looking at the centre. Defaults to the initial view's direction.
 */
export function frameBox(camera, controls, box, direction = DEFAULT_DIRECTION) {
  const center = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 0.5);
  let far = (1.1 * sphereDistance(camera, radius)) / FIT_NDC;  // the sphere fits with a margin
  let near = 0;
  for (let i = 0; i < 40; ++i) {  // bisection on the distance
    const middle = (near + far) / 2;
    placeCamera(camera, center, direction, middle);
    if (boxInView(camera, box, FIT_NDC)) far = middle;
    else near = middle;
  }
  placeCamera(camera, center, direction, far);
  controls.target.copy(center);
  controls.update();
}

/** The current viewing direction: unit, from the orbit target towards the camera. */
export function viewDirection(camera, controls) {
  const direction = camera.position.clone().sub(controls.target);
  return direction.lengthSq() > 0 ? direction.normalize() : DEFAULT_DIRECTION.clone();
}
