// What the replay page (replay.js) and the explorer page (explorer.js) draw alike: the robot
// from its URDF visual shapes, as lib/src/replay.cpp writes them (replay::scene_json): each
// shape's kind, size, colour, body and placement [px, py, pz, qx, qy, qz, qw] in its body frame.
import * as THREE from 'three';

export function el(tag, attrs = {}, text = '') {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text) e.textContent = text;
  return e;
}

export function geometryOf(shape) {
  if (shape.kind === 'box') return new THREE.BoxGeometry(...shape.size);
  if (shape.kind === 'sphere') return new THREE.SphereGeometry(shape.radius, 24, 16);
  // URDF cylinders lie along their local z, three.js cylinders along y.
  const g = new THREE.CylinderGeometry(shape.radius, shape.radius, shape.length, 32);
  g.rotateX(Math.PI / 2);
  return g;
}

export function setPose(object, pose, offset = 0) {
  object.position.set(pose[offset], pose[offset + 1], pose[offset + 2]);
  object.quaternion.set(pose[offset + 3], pose[offset + 4], pose[offset + 5], pose[offset + 6]);
}

/// One copy of the robot: a group per body holding its shapes. `lit: 'lambert'` shades with
/// THREE.MeshLambertMaterial, cheaper per pixel than the physically based default.
export function buildRobot(data, opacity, lit = 'standard') {
  const root = new THREE.Group();
  const bodies = [];
  for (let i = 0; i < data.bodies; ++i) {
    const g = new THREE.Group();
    root.add(g);
    bodies.push(g);
  }
  for (const shape of data.shapes) {
    const common = { color: shape.color, transparent: opacity < 1, opacity, depthWrite: opacity >= 1 };
    const material = lit === 'lambert' ? new THREE.MeshLambertMaterial(common)
      : new THREE.MeshStandardMaterial({ ...common, roughness: 0.55, metalness: 0.1 });
    const mesh = new THREE.Mesh(geometryOf(shape), material);
    setPose(mesh, shape.placement);
    (shape.body < 0 ? root : bodies[shape.body]).add(mesh);
  }
  return { root, bodies };
}

/// A z-up scene with the pages' background, lights, floor grid (`grid` metres square, 0.1 m
/// cells) and base axes.
export function baseScene(grid = 4) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f5f7);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8890a0, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(2, -3, 4);
  scene.add(sun);
  const floor = new THREE.GridHelper(grid, Math.round(grid / 0.1), 0xb0b4bc, 0xd6d8de);
  floor.rotation.x = Math.PI / 2;  // the URDF world is z-up
  scene.add(floor);
  scene.add(new THREE.AxesHelper(0.2));
  return scene;
}
