// What the replay page (replay.js) and the explorer page (explorer.js) draw alike: the robot
// from its URDF visual shapes, as lib/src/visuals/replay.cpp writes them (replay::scene_json): each
// shape's kind, size, colour, body and placement [px, py, pz, qx, qy, qz, qw] in its body frame.
import * as THREE from 'three';

export function el(tag, attrs = {}, text = '') {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text) e.textContent = text;
  return e;
}

/// A shape's triangles, round ones with `segments` around (fewer for the explorer, which
/// software WebGL draws in five copies per frame).
export function geometryOf(shape, segments = 32) {
  if (shape.kind === 'box') return new THREE.BoxGeometry(...shape.size);
  if (shape.kind === 'sphere') return new THREE.SphereGeometry(shape.radius, (segments * 3) / 4, segments / 2);
  // URDF cylinders lie along their local z, three.js cylinders along y.
  const g = new THREE.CylinderGeometry(shape.radius, shape.radius, shape.length, segments);
  g.rotateX(Math.PI / 2);
  return g;
}

export function setPose(object, pose, offset = 0) {
  object.position.set(pose[offset], pose[offset + 1], pose[offset + 2]);
  object.quaternion.set(pose[offset + 3], pose[offset + 4], pose[offset + 5], pose[offset + 6]);
}

/// One copy of the robot (the replay page's): a group per body holding its shapes.
export function buildRobot(data, opacity) {
  const root = new THREE.Group();
  const bodies = [];
  for (let i = 0; i < data.bodies; ++i) {
    const g = new THREE.Group();
    root.add(g);
    bodies.push(g);
  }
  for (const shape of data.shapes) {
    const common = { color: shape.color, transparent: opacity < 1, opacity, depthWrite: opacity >= 1 };
    const material = new THREE.MeshStandardMaterial({ ...common, roughness: 0.55, metalness: 0.1 });
    const mesh = new THREE.Mesh(geometryOf(shape), material);
    setPose(mesh, shape.placement);
    (shape.body < 0 ? root : bodies[shape.body]).add(mesh);
  }
  return { root, bodies };
}

/// The pages' lights: a hemisphere light (three.js's default "up", +y) and a sun.
export const LIGHTS = { sky: 0xffffff, ground: 0x8890a0, hemisphere: 1.6, sun: 0xffffff, sunIntensity: 1.8, sunAt: [2, -3, 4] };

// Linear colour to the canvas's sRGB (three.js's sRGBTransferOETF).
const TO_SRGB = `
vec3 toSRGB(vec3 linear) {
  return mix(pow(linear, vec3(0.41666)) * 1.055 - vec3(0.055), linear * 12.92, vec3(lessThanEqual(linear, vec3(0.0031308))));
}`;

// Lambert shading (as THREE.MeshLambertMaterial under LIGHTS) computed once per vertex, not per
// pixel: the fragments only write the vertex's colour, which software WebGL fills cheaply.
// With BODIES defined, one mesh holds a whole robot: each vertex is moved by its body's pose (a
// uniform array) and has its shape's colour; without, the mesh's own placement and one colour.
const LIT_VERTEX = TO_SRGB + `
#ifdef BODIES
uniform mat4 bodies[BODIES];
attribute float body;
attribute vec3 tint;
#else
uniform vec3 tint;
#endif
uniform vec3 sunDirection, sunColor, skyColor, groundColor;
varying vec3 vColor;
void main() {
#ifdef BODIES
  mat4 pose = bodies[int(body)];
  vec3 n = normalize(mat3(pose) * normal);
#else
  mat4 pose = modelMatrix;
  vec3 n = normalize(transpose(inverse(mat3(pose))) * normal);  // a scaled shape's normals
#endif
  vec3 irradiance = sunColor * max(dot(n, sunDirection), 0.0) + mix(groundColor, skyColor, 0.5 * n.y + 0.5);
  vec3 linear = tint * irradiance * 0.3183098862;  // Lambert's BRDF: the albedo over pi
  vColor = toSRGB(linear);
  gl_Position = projectionMatrix * viewMatrix * (pose * vec4(position, 1.0));
}`;
const LIT_FRAGMENT = `
uniform float opacity;
varying vec3 vColor;
void main() { gl_FragColor = vec4(vColor, opacity); }`;

/// The vertex-lit material: `color` (a CSS colour) for a single shape, or the robot's `bodies`
/// (an array of Matrix4, one per body) for a merged robot.
export function litMaterial({ color = null, bodies = null, opacity = 1 }) {
  const linear = (hex, k) => new THREE.Color(hex).multiplyScalar(k);
  const uniforms = {
    sunDirection: { value: new THREE.Vector3(...LIGHTS.sunAt).normalize() },
    sunColor: { value: linear(LIGHTS.sun, LIGHTS.sunIntensity) },
    skyColor: { value: linear(LIGHTS.sky, LIGHTS.hemisphere) },
    groundColor: { value: linear(LIGHTS.ground, LIGHTS.hemisphere) },
    opacity: { value: opacity },
  };
  if (bodies) uniforms.bodies = { value: bodies };
  else uniforms.tint = { value: new THREE.Color(color) };  // linear, as three.js's materials take it
  return new THREE.ShaderMaterial({
    uniforms, vertexShader: LIT_VERTEX, fragmentShader: LIT_FRAGMENT, defines: bodies ? { BODIES: bodies.length } : {},
    transparent: opacity < 1, depthWrite: opacity >= 1,
  });
}

// Unlit lines (the floor grid, the axes, the mass ellipsoid's rings) with their colour made sRGB
// once per vertex, not per pixel as THREE.LineBasicMaterial does.
const LINE_VERTEX = TO_SRGB + `
#ifndef USE_COLOR
uniform vec3 tint;
#endif
varying vec3 vColor;
void main() {
#ifdef USE_COLOR
  vColor = toSRGB(color);
#else
  vColor = toSRGB(tint);
#endif
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}`;

/// The line material: one CSS `color`, or without it the geometry's vertex colours (linear).
export function lineMaterial(color = null) {
  const uniforms = { opacity: { value: 1 } };
  if (color) uniforms.tint = { value: new THREE.Color(color) };
  return new THREE.ShaderMaterial({ uniforms, vertexShader: LINE_VERTEX, fragmentShader: LIT_FRAGMENT, vertexColors: !color });
}

/// One copy of the robot as one mesh (one draw call): every shape's triangles, placed in its
/// body's frame, in one geometry whose vertices carry their body's index and their shape's
/// colour. `pose(poses)` moves the bodies: poses[i] = [px, py, pz, qx, qy, qz, qw] of body i;
/// `dispose()` frees its buffers when the page shows another robot.
export function buildMergedRobot(data, opacity, segments = 16) {
  const positions = [], normals = [], tints = [], owners = [], indices = [];
  const place = new THREE.Matrix4(), color = new THREE.Color();
  for (const shape of data.shapes) {
    const g = geometryOf(shape, segments);
    const p = shape.placement;
    g.applyMatrix4(place.compose(new THREE.Vector3(p[0], p[1], p[2]), new THREE.Quaternion(p[3], p[4], p[5], p[6]), new THREE.Vector3(1, 1, 1)));
    const base = positions.length / 3, n = g.attributes.position.count;
    positions.push(...g.attributes.position.array);
    normals.push(...g.attributes.normal.array);
    color.set(shape.color);  // linear, as three.js's materials take it
    for (let i = 0; i < n; ++i) { tints.push(color.r, color.g, color.b); owners.push(shape.body < 0 ? data.bodies : shape.body); }
    for (const i of g.index.array) indices.push(base + i);
    g.dispose();
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new THREE.Float32BufferAttribute(normals, 3));
  geometry.setAttribute('tint', new THREE.Float32BufferAttribute(tints, 3));
  geometry.setAttribute('body', new THREE.Float32BufferAttribute(owners, 1));
  geometry.setIndex(indices);
  const bodies = Array.from({ length: data.bodies + 1 }, () => new THREE.Matrix4());  // the last: the base
  const material = litMaterial({ bodies, opacity });
  const root = new THREE.Mesh(geometry, material);
  root.frustumCulled = false;  // its bounding sphere is the bodies' at rest
  const position = new THREE.Vector3(), turn = new THREE.Quaternion(), one = new THREE.Vector3(1, 1, 1);
  const pose = (poses) => poses.forEach((p, i) => bodies[i].compose(position.set(p[0], p[1], p[2]), turn.set(p[3], p[4], p[5], p[6]), one));
  const dispose = () => { geometry.dispose(); material.dispose(); };
  return { root, pose, dispose };
}

/// A z-up scene with the pages' background, lights, floor grid (`grid` metres square, 0.1 m
/// cells) and base axes.
export function baseScene(grid = 4) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f5f7);
  scene.add(new THREE.HemisphereLight(LIGHTS.sky, LIGHTS.ground, LIGHTS.hemisphere));
  const sun = new THREE.DirectionalLight(LIGHTS.sun, LIGHTS.sunIntensity);
  sun.position.set(...LIGHTS.sunAt);
  scene.add(sun);
  // The grid and the axes as one set of line segments: one draw call.
  const floor = new THREE.GridHelper(grid, Math.round(grid / 0.1), 0xb0b4bc, 0xd6d8de);
  floor.geometry.rotateX(Math.PI / 2);  // the URDF world is z-up
  const axes = new THREE.AxesHelper(0.2);
  const lines = new THREE.BufferGeometry();
  for (const name of ['position', 'color']) {
    const a = floor.geometry.attributes[name].array, b = axes.geometry.attributes[name].array;
    const both = new Float32Array(a.length + b.length);
    both.set(a);
    both.set(b, a.length);
    lines.setAttribute(name, new THREE.BufferAttribute(both, 3));
  }
  floor.geometry.dispose();
  axes.dispose();
  floor.material.dispose();
  scene.add(new THREE.LineSegments(lines, lineMaterial()));
  return scene;
}
