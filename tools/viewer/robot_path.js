// The robot's path: map.glb's line strip "robot_path" (world positions),
// redrawn as a 3-pixel line a little above the floor with a green start and
// a red end marker (doc/viewer.md).
import * as THREE from 'three';
import {Line2} from 'three/addons/lines/Line2.js';
import {LineGeometry} from 'three/addons/lines/LineGeometry.js';
import {LineMaterial} from 'three/addons/lines/LineMaterial.js';

const PATH_NAME = 'robot_path';
const PATH_COLOUR = 0xe0561b;
const LIFT_M = 0.03;  // above the floor the path runs on, against z-fighting
const LINE_WIDTH_PX = 3;

function findPathLine(model) {
  let found = null;
  model.traverse((object) => {
    const name = object.userData.name ?? object.name;
    if (!found && object.isLine && name === PATH_NAME) found = object;
  });
  return found;
}

function marker(position, colour, radius) {
  const sphere = new THREE.Mesh(new THREE.SphereGeometry(radius, 12, 8),
                                new THREE.MeshBasicMaterial({color: colour}));
  sphere.position.copy(position);
  return sphere;
}

/**
 * Takes the path out of `model` (its matrices up to date) and returns
 * {object, positions, lengthM} with `object` a group to add to the scene, or
 * null when the model has no path. `markerRadius` in metres.
 */
export function extractRobotPath(model, markerRadius) {
  const line = findPathLine(model);
  if (!line) return null;
  line.removeFromParent();
  const attribute = line.geometry.attributes.position;
  const points = [];
  for (let i = 0; i < attribute.count; ++i) {
    const p = new THREE.Vector3().fromBufferAttribute(attribute, i).applyMatrix4(line.matrixWorld);
    p.z += LIFT_M;
    points.push(p);
  }
  if (points.length < 2) return null;
  let lengthM = 0;
  for (let i = 1; i < points.length; ++i) lengthM += points[i].distanceTo(points[i - 1]);

  const geometry = new LineGeometry();
  geometry.setPositions(points.flatMap((p) => p.toArray()));
  const material = new LineMaterial({color: PATH_COLOUR, linewidth: LINE_WIDTH_PX});
  const path = new Line2(geometry, material);
  path.computeLineDistances();
  const group = new THREE.Group();
  group.name = PATH_NAME;
  group.add(path, marker(points[0], 0x1f9d3a, markerRadius),
            marker(points[points.length - 1], 0xc62828, markerRadius));
  return {object: group, positions: points.length, lengthM};
}
