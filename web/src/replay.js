// The opspace replay viewer. esbuild bundles this file with three.js into one script
// (build/<preset>/web/opspace-replay.js) that lib/src/visuals/replay.cpp inlines into each replay
// page, after a <script id="opspace-replay-data" type="application/json"> block holding the
// run: shapes of the robot, per-frame body poses, markers (targets, trails, arrows, planes)
// and head-up values. The data format is described in docs/visuals.md.
//
// URL hash options (combine with &): t=SECONDS starts paused at that time; ghosts=N draws N
// faded copies of the robot spread over the run (a stroboscopic picture); speed=X.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { baseScene, buildRobot, el, setPose } from './scene.js';

const api = { ready: false, frames: 0 };
window.opspaceReplay = api;

const CSS = `
html, body { margin: 0; height: 100%; overflow: hidden; font: 14px system-ui, sans-serif; color: #1d2330; }
#stage { position: absolute; inset: 0 0 44px 0; }
#stage canvas { width: 100%; height: 100%; display: block; }
#hud { position: absolute; top: 8px; left: 10px; background: rgba(255,255,255,0.85); padding: 6px 10px; border-radius: 6px; max-width: 46%; }
#hud h1 { font-size: 15px; margin: 0 0 2px 0; }
#hud .sub { margin: 0 0 4px 0; color: #555; }
#readout { margin: 4px 0; font: 13px ui-monospace, monospace; }
#legend { list-style: none; margin: 0; padding: 0; font-size: 12px; }
.swatch { display: inline-block; width: 10px; height: 10px; margin-right: 6px; border-radius: 2px; }
#bar { position: absolute; left: 0; right: 0; bottom: 0; height: 44px; display: flex; gap: 10px; align-items: center; padding: 0 10px; background: #e6e8ec; box-sizing: border-box; }
#slider { flex: 1; }
#clock { font: 13px ui-monospace, monospace; min-width: 120px; }
#no-webgl { padding: 2em; }
`;

function hashOptions() {
  const options = {};
  for (const part of window.location.hash.replace(/^#/, '').split('&')) {
    const [k, v] = part.split('=');
    if (k) options[k] = v === undefined ? true : v;
  }
  return options;
}

function poseRobot(robot, data, frame) {
  const poses = data.poses[frame];
  for (let i = 0; i < data.bodies; ++i) setPose(robot.bodies[i], poses, 7 * i);
}

function vectorAt(track, frame) {
  const v = track.length === 1 ? track[0] : track[Math.min(frame, track.length - 1)];
  return new THREE.Vector3(v[0], v[1], v[2]);
}

/// Markers: each returns an update(frame) function.
function buildMarker(scene, m) {
  const color = new THREE.Color(m.color);
  if (m.kind === 'point') {
    const mesh = new THREE.Mesh(new THREE.SphereGeometry(m.radius, 20, 14),
      new THREE.MeshBasicMaterial({ color, transparent: true, opacity: 0.8 }));
    scene.add(mesh);
    return (frame) => mesh.position.copy(vectorAt(m.positions, frame));
  }
  if (m.kind === 'trail') {
    const points = m.positions.map((p) => new THREE.Vector3(p[0], p[1], p[2]));
    const geometry = new THREE.BufferGeometry().setFromPoints(points);
    const line = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color }));
    scene.add(line);
    return (frame) => geometry.setDrawRange(0, Math.min(frame + 1, points.length));
  }
  if (m.kind === 'arrow') {
    const arrow = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 0.1, color);
    scene.add(arrow);
    return (frame) => {
      const v = vectorAt(m.vectors, frame).multiplyScalar(m.scale);
      const length = v.length();
      arrow.visible = length > 1e-9;
      arrow.position.copy(vectorAt(m.origins, frame));
      if (arrow.visible) {
        arrow.setDirection(v.clone().normalize());
        arrow.setLength(length, Math.min(0.3 * length, 0.05), Math.min(0.15 * length, 0.025));
      }
    };
  }
  if (m.kind === 'plane') {
    const mesh = new THREE.Mesh(new THREE.PlaneGeometry(m.size, m.size),
      new THREE.MeshStandardMaterial({ color, transparent: true, opacity: 0.35, side: THREE.DoubleSide }));
    const normal = new THREE.Vector3(...m.normal).normalize();
    mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), normal);
    mesh.position.set(...m.point);
    scene.add(mesh);
    return () => {};
  }
  console.warn(`opspace replay: unknown marker kind '${m.kind}'`);
  return () => {};
}

function frameAt(data, t) {
  // Frames are evenly spaced in time; find the last frame not after t.
  const times = data.t;
  let lo = 0, hi = times.length - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (times[mid] <= t) lo = mid; else hi = mid - 1;
  }
  return lo;
}

function main() {
  const data = JSON.parse(document.getElementById('opspace-replay-data').textContent);
  const options = hashOptions();
  const n = data.t.length;
  api.frames = n;
  document.title = data.title;
  document.head.append(el('style', {}, CSS));

  const stage = el('div', { id: 'stage' });
  const hud = el('div', { id: 'hud' });
  hud.append(el('h1', {}, data.title));
  if (data.subtitle) hud.append(el('p', { class: 'sub' }, data.subtitle));
  const readout = el('pre', { id: 'readout' });
  // As many lines as show() writes, so that the panel has its final size when the view is framed.
  readout.textContent = ['t = 0.000 s', ...data.hud.map((h) => `${h.label}: 0.000`)].join('\n');
  hud.append(readout);
  const legend = el('ul', { id: 'legend' });
  legend.append(el('li', {}, 'robot: URDF visual shapes'));
  for (const m of data.markers) {
    if (!m.label) continue;
    const li = el('li');
    li.append(el('span', { class: 'swatch', style: `background:${m.color}` }), document.createTextNode(m.label));
    legend.append(li);
  }
  hud.append(legend);
  const bar = el('div', { id: 'bar' });
  const play = el('button', { id: 'play', type: 'button' }, 'Pause');
  const slider = el('input', { id: 'slider', type: 'range', min: '0', max: String(n - 1), value: '0', step: '1' });
  const speed = el('select', { id: 'speed' });
  for (const s of ['0.25', '0.5', '1', '2', '4']) speed.append(el('option', { value: s }, `${s}x`));
  speed.value = options.speed && ['0.25', '0.5', '1', '2', '4'].includes(options.speed) ? options.speed : '1';
  const clock = el('span', { id: 'clock' });
  bar.append(play, slider, speed, clock);
  document.body.append(stage, hud, bar);

  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  } catch (e) {
    const msg = el('p', { id: 'no-webgl' }, 'This browser could not create a WebGL context, so the 3D replay cannot be drawn. The plots next to this page show the same run.');
    stage.append(msg);
    console.error(`opspace replay: WebGL unavailable: ${e.message}`);
    return;
  }
  renderer.setPixelRatio(window.devicePixelRatio);
  stage.append(renderer.domElement);

  const scene = baseScene();

  const robot = buildRobot(data, 1);
  scene.add(robot.root);
  const ghostCount = Math.max(0, Math.min(24, parseInt(options.ghosts || '0', 10) || 0));
  for (let k = 0; k < ghostCount; ++k) {
    const ghost = buildRobot(data, 0.28);
    poseRobot(ghost, data, Math.round(((k + 0.5) / ghostCount) * (n - 1)));
    scene.add(ghost.root);
  }
  const updates = data.markers.map((m) => buildMarker(scene, m));

  // Frame the motion: the box around every body origin over the run, and around the points,
  // trails and arrow origins, which show the tip (a body origin can be far from its link's
  // end: the 3R arm's forearm reaches 0.5 m past it).
  const box = new THREE.Box3();
  const step = Math.max(1, Math.floor(n / 100));
  for (let f = 0; f < n; f += step) {
    for (let i = 0; i < data.bodies; ++i) {
      const p = data.poses[f];
      box.expandByPoint(new THREE.Vector3(p[7 * i], p[7 * i + 1], p[7 * i + 2]));
    }
  }
  for (const m of data.markers) {
    if (!['point', 'trail', 'arrow'].includes(m.kind)) continue;
    for (let f = 0; f < m.positions.length; f += step) box.expandByPoint(vectorAt(m.positions, f));
  }
  box.expandByPoint(new THREE.Vector3(0, 0, 0));
  const center = box.getCenter(new THREE.Vector3());
  const radius = Math.max(0.3, box.getSize(new THREE.Vector3()).length() / 2);
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  camera.up.set(0, 0, 1);
  const view = new THREE.Vector3(...(data.view || [1, -1, 0.7])).normalize();

  // The info panel covers the top left of the stage: the scene is framed in the larger of the
  // free areas beside it and below it, by moving the image's centre there (a view offset).
  function freeArea(w, h) {
    const right = hud.offsetLeft + hud.offsetWidth + 8, bottom = hud.offsetTop + hud.offsetHeight + 8;
    const beside = { x: right, y: 0, w: Math.max(1, w - right), h };
    const below = { x: 0, y: bottom, w, h: Math.max(1, h - bottom) };
    const side = (a) => Math.min(a.w, a.h);
    return side(beside) >= side(below) ? beside : below;
  }
  function stageSize() {
    return [stage.clientWidth || window.innerWidth, stage.clientHeight || window.innerHeight];
  }
  {
    // Far enough that the sphere around the framed box spans 1/1.45 of the stage's height
    // (vertical field of view 40 deg), or less if the free area is smaller than that.
    const [w, h] = stageSize();
    const area = freeArea(w, h);
    const shrink = Math.max(1, h / 1.45 / Math.min(area.w, area.h));
    camera.position.copy(center).addScaledVector(view, radius / Math.tan((20 * Math.PI) / 180) * 1.45 * shrink);
  }
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(center);
  controls.update();

  function resize() {
    const [w, h] = stageSize();
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    const area = freeArea(w, h);
    camera.setViewOffset(w, h, w / 2 - (area.x + area.w / 2), h / 2 - (area.y + area.h / 2), w, h);
    camera.updateProjectionMatrix();
  }
  window.addEventListener('resize', resize);
  resize();

  let frame = 0, playing = !('t' in options), time = data.t[0];
  function show(f) {
    frame = Math.max(0, Math.min(n - 1, f));
    poseRobot(robot, data, frame);
    for (const update of updates) update(frame);
    slider.value = String(frame);
    const lines = [`t = ${data.t[frame].toFixed(3)} s`];
    for (const h of data.hud) lines.push(`${h.label}: ${h.values[frame].toPrecision(4)}`);
    readout.textContent = lines.join('\n');
    clock.textContent = `${data.t[frame].toFixed(2)} / ${data.t[n - 1].toFixed(2)} s`;
  }
  function setPlaying(p) {
    playing = p;
    play.textContent = p ? 'Pause' : 'Play';
  }
  play.addEventListener('click', () => setPlaying(!playing));
  slider.addEventListener('input', () => {
    setPlaying(false);
    time = data.t[parseInt(slider.value, 10)];
    show(parseInt(slider.value, 10));
  });
  window.addEventListener('keydown', (e) => {
    if (e.key === ' ') { setPlaying(!playing); e.preventDefault(); }
  });

  if ('t' in options) time = parseFloat(options.t) || 0;
  setPlaying(playing);
  show(frameAt(data, time));

  let last = performance.now();
  function tick(now) {
    const elapsed = Math.min(0.1, (now - last) / 1000);
    last = now;
    if (playing && n > 1) {
      time += elapsed * parseFloat(speed.value);
      if (time > data.t[n - 1]) time = data.t[0];
      show(frameAt(data, time));
    }
    controls.update();
    renderer.render(scene, camera);
    requestAnimationFrame(tick);
  }
  renderer.render(scene, camera);
  requestAnimationFrame(tick);

  api.setFrame = (f) => { setPlaying(false); show(f); renderer.render(scene, camera); };
  api.setRobotVisible = (v) => { robot.root.visible = v; renderer.render(scene, camera); };
  api.ready = true;
}

try {
  main();
} catch (e) {
  console.error(`opspace replay: ${e.stack || e}`);
}
