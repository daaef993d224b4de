// The opspace explorer page. esbuild bundles this file with three.js into
// build/<preset>/web/opspace-explorer-viewer.js, which opspace-explorer (web/explorer/main.cpp)
// inlines into the page after two blocks: <script id="opspace-explorer-data"> with the four
// robots (Model text, tip, joints, shapes) and the library compiled to WebAssembly
// (createOpspaceCore, web/explorer/wasm_api.cpp). Every number drawn comes from that module:
// this file only turns them into pictures.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { sliderRange } from './joint_range.mjs';
import { baseScene, buildMergedRobot, el, lineMaterial, litMaterial } from './scene.js';

// The test hook (web/test/check_explorer.mjs).
const api = { ready: false, redrawMs: [], computeMs: [], waitForGpu: false };
window.opspaceExplorer = api;

const TYPE_COLORS = { 1: '#e67e22', 2: '#8e44ad' };  // Type I orange, Type II purple
const TYPE_NAMES = { 1: 'Type I', 2: 'Type II' };
const DIRECTIONS = { X0: [1, 0, 0], Y0: [0, 1, 0], Z0: [0, 0, 1] };

const CSS = `
html, body { margin: 0; height: 100%; font: 13px system-ui, sans-serif; color: #1d2330; background: #f4f5f7; }
#side { position: absolute; left: 0; top: 0; bottom: 0; width: 370px; overflow-y: auto; padding: 8px 12px; box-sizing: border-box; background: #fff; border-right: 1px solid #d6d8de; }
#side h1 { font-size: 16px; margin: 4px 0; }
#side h2 { font-size: 13px; margin: 12px 0 4px 0; }
#side p { margin: 4px 0; color: #444; line-height: 1.35; }
.row { display: grid; grid-template-columns: 96px 1fr 72px; gap: 6px; align-items: center; margin: 2px 0; }
.row input[type=range] { width: 100%; }
.num { font: 12px ui-monospace, monospace; text-align: right; }
#numbers { overflow-x: auto; font: 11px ui-monospace, monospace; white-space: pre; background: #f4f5f7; padding: 6px; border-radius: 4px; }
.swatch { display: inline-block; width: 10px; height: 10px; margin-right: 6px; border-radius: 2px; }
#views { position: absolute; left: 370px; right: 0; top: 0; bottom: 0; display: grid; grid-template-rows: 3fr 2fr; grid-template-columns: 1fr 1fr; }
#canvas { position: absolute; left: 0; top: 0; width: 100%; height: 100%; display: block; }
.view { position: relative; border: 1px solid #d6d8de; overflow: hidden; touch-action: none; }
.view .label { position: absolute; left: 8px; top: 6px; background: rgba(255,255,255,0.85); padding: 3px 6px; border-radius: 4px; max-width: 90%; }
#main { grid-column: 1 / 3; }
`;

function degrees(joint, value) { return joint.prismatic ? `${value.toFixed(3)} m` : `${(value * 180 / Math.PI).toFixed(1)}°`; }

/// The WebAssembly module's two calls, with the doubles passed through its heap.
function coreApi(core) {
  const load = core.cwrap('explorer_load', 'number', ['string', 'string', 'string', 'number', 'number', 'number']);
  const viewRaw = core.cwrap('explorer_view', 'number', ['number', 'number', 'number', 'number', 'number', 'number', 'number', 'number', 'number']);
  const error = core.cwrap('explorer_error', 'string', []);
  const buffer = core._malloc(8 * 64);
  return {
    load(robot) {
      const handle = load(robot.model, `explorer:${robot.key}`, robot.tip_link, ...robot.tip_point);
      if (handle < 0) throw new Error(`opspace explorer: cannot load ${robot.key}: ${error()}`);
      return handle;
    },
    view(handle, request) {
      core.HEAPF64.set(request.q, buffer / 8);
      const text = viewRaw(handle, buffer, request.q.length, ...request.u, request.tipS, request.selfJoint, request.selfS);
      if (!text) throw new Error(`opspace explorer: ${error()}`);
      return JSON.parse(core.UTF8ToString(text));
    },
  };
}

/// The unit sphere's three great circles in the coordinate planes, as line segments: scaled and
/// turned like an ellipsoid, they are its three principal sections (cheaper to draw than a
/// wireframe, and they show the axes).
function principalRings(segments = 64) {
  const points = [];
  for (let plane = 0; plane < 3; ++plane) {
    for (let i = 0; i < segments; ++i) {
      for (const k of [i, i + 1]) {
        const a = (2 * Math.PI * k) / segments, p = [0, 0, 0];
        p[plane] = Math.cos(a);
        p[(plane + 1) % 3] = Math.sin(a);
        points.push(new THREE.Vector3(...p));
      }
    }
  }
  return new THREE.BufferGeometry().setFromPoints(points);
}

/// An ellipsoid from its axes (columns) and radii; null radii (infinite) are drawn at `clip`.
function placeEllipsoid(mesh, axes, radii, scale, clip) {
  const r = radii.map((v) => (v === null ? clip : Math.min(clip, Math.max(1e-3, v * scale))));
  const m = new THREE.Matrix4().makeBasis(new THREE.Vector3(...axes[0]), new THREE.Vector3(...axes[1]), new THREE.Vector3(...axes[2]));
  if (m.determinant() < 0) m.makeBasis(new THREE.Vector3(...axes[0]), new THREE.Vector3(...axes[1]), new THREE.Vector3(...axes[2]).negate());
  mesh.quaternion.setFromRotationMatrix(m);
  mesh.scale.set(r[0], r[1], r[2]);
}

/// One WebGL canvas behind the three view boxes (one context, one frame to wait for); each view
/// draws its scene into its box's rectangle.
function makeRenderer(views) {
  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setScissorTest(true);
  renderer.domElement.id = 'canvas';
  views.prepend(renderer.domElement);
  return renderer;
}

/// A view: its box (which takes the mouse), camera looking at the robot, controls.
function makeView(renderer, box, labelHtml) {
  const label = el('div', { class: 'label' });
  label.innerHTML = labelHtml;
  box.append(label);
  // A 2 m floor: the arms reach under a metre, and software WebGL pays for every line pixel.
  const scene = baseScene(2);
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, box);
  const view = { scene, camera, controls, box };
  view.frame = (center, radius) => {
    camera.position.copy(center).add(new THREE.Vector3(1.3, -1.6, 0.9).normalize().multiplyScalar(radius / Math.tan(Math.PI / 9) * 1.1));
    controls.target.copy(center);
    controls.update();
  };
  const rect = () => {
    const r = box.getBoundingClientRect(), c = renderer.domElement.getBoundingClientRect();
    return { x: r.left - c.left, y: c.bottom - r.bottom, w: Math.max(1, r.width), h: Math.max(1, r.height) };
  };
  // The box's place in the canvas, measured when the page is laid out anew (resize), not on every
  // redraw: reading it after the numbers' text changed would force a layout inside the redraw.
  let place = null;
  view.resize = () => {
    place = rect();
    camera.aspect = place.w / place.h;
    camera.updateProjectionMatrix();
  };
  view.render = () => {
    const r = place || rect();
    renderer.setViewport(r.x, r.y, r.w, r.h);
    renderer.setScissor(r.x, r.y, r.w, r.h);
    renderer.render(scene, camera);
  };
  controls.addEventListener('change', view.render);  // drawn on demand: when the camera or q moves
  return view;
}

function main() {
  const data = JSON.parse(document.getElementById('opspace-explorer-data').textContent);
  document.head.append(el('style', {}, CSS));
  const side = el('div', { id: 'side' });
  const views = el('div', { id: 'views' });
  document.body.append(side, views);
  side.append(el('h1', {}, 'opspace explorer'));
  side.append(el('p', {}, 'Every number on this page is computed by the opspace library, compiled from its C++ to WebAssembly: the same code the problems run.'));
  const robotMenu = el('select', { id: 'robot' });
  for (const r of data.robots) robotMenu.append(el('option', { value: r.key }, r.title));
  side.append(robotMenu);
  const caption = el('p', { id: 'caption' });
  const jointsBox = el('div', { id: 'joints' });
  side.append(caption, el('h2', {}, 'Joints q'), jointsBox);

  side.append(el('h2', {}, 'Tip motion δx (problem 1a-vi)'));
  side.append(el('p', {}, 'The same tip displacement δx through δq = J+ δx (bottom left) and δq = Jbar δx (bottom right).'));
  const tipDir = el('select', { id: 'tip-direction' });
  for (const d of Object.keys(DIRECTIONS)) tipDir.append(el('option', { value: d }, `along ${d}`));
  const tipSlider = el('input', { id: 'tip-s', type: 'range', min: '-0.2', max: '0.2', step: '0.005', value: '0' });
  const tipValue = el('span', { class: 'num' });
  const tipRow = el('div', { class: 'row' });
  tipRow.append(tipDir, tipSlider, tipValue);
  side.append(tipRow);

  side.append(el('h2', {}, 'Self-motion (null space of Jv)'));
  side.append(el('p', {}, 'The motion δq0 = s e_j of one joint, projected by N = I - J+ Jv (left) and by N = I - Jbar Jv (right). Both keep the tip still; they are different self-motions.'));
  const selfJoint = el('select', { id: 'self-joint' });
  const selfSlider = el('input', { id: 'self-s', type: 'range', min: '-1', max: '1', step: '0.01', value: '0' });
  const selfValue = el('span', { class: 'num' });
  const selfRow = el('div', { class: 'row' });
  selfRow.append(selfJoint, selfSlider, selfValue);
  side.append(selfRow);

  side.append(el('h2', {}, 'At this configuration'));
  const numbers = el('div', { id: 'numbers' });
  side.append(numbers);
  const legend = el('div', { id: 'legend' });
  legend.innerHTML = [
    ['#3498db', 'velocity ellipsoid {Jv δq : |δq| ≤ 1}: semi-axes σ_i along u_i (SVD of Jv)'],
    ['#27ae60', 'mass ellipsoid {v : vᵀ Λv⁻¹ v ≤ 1}, drawn as its three principal sections: its radius along u is √m_u, the effective mass m_u = 1 / (uᵀ Λv⁻¹ u) the tip presents along u. Drawn clipped where it is infinite'],
    [TYPE_COLORS[1], 'Type I singular direction: a self-motion moves the tip along it at second order (a potential whose minimum lies on that motion gets there)'],
    [TYPE_COLORS[2], 'Type II singular direction: no self-motion does; joints that move the tip elsewhere must first rotate the direction away'],
  ].map(([c, t]) => `<p><span class="swatch" style="background:${c}"></span>${t}</p>`).join('');
  side.append(legend);

  const mainBox = el('div', { id: 'main', class: 'view' });
  const leftBox = el('div', { id: 'pinv', class: 'view' });
  const rightBox = el('div', { id: 'dcinv', class: 'view' });
  views.append(mainBox, leftBox, rightBox);
  let main, left, right, renderer;
  try {
    renderer = makeRenderer(views);
    main = makeView(renderer, mainBox, '<b>q</b>: the arm, the two ellipsoids at the tip (drawn to scale per robot), the singular directions');
    left = makeView(renderer, leftBox, '<b>J+</b> and <b>I − J+ J</b> (pseudo-inverse): faint, the arm at q; solid, after the two motions');
    right = makeView(renderer, rightBox, '<b>Jbar</b> and <b>I − Jbar J</b> (dynamically consistent): faint, the arm at q; solid, after the two motions');
  } catch (e) {
    views.append(el('p', {}, 'This browser could not create a WebGL context, so the explorer cannot draw.'));
    console.error(`opspace explorer: WebGL unavailable: ${e.message}`);
    return;
  }
  const allViews = [main, left, right];
  const resize = () => {
    renderer.setSize(views.clientWidth || 800, views.clientHeight || 600, false);
    allViews.forEach((v) => v.resize());
  };
  window.addEventListener('resize', () => { resize(); draw(); });

  // 24 x 16 facets (was 40 x 24): software WebGL pays for every triangle, even a small one.
  const velocity = new THREE.Mesh(new THREE.SphereGeometry(1, 24, 16), litMaterial({ color: '#3498db', opacity: 0.45 }));
  const mass = new THREE.LineSegments(principalRings(), lineMaterial('#1e8449'));
  main.scene.add(velocity, mass);
  let arrows = [];

  return createOpspaceCore().then((module) => {
    const core = coreApi(module);
    const robots = data.robots.map((r) => ({ ...r, handle: core.load(r) }));
    let robot = null, q = [], drawn = { main: null, left: null, right: null, leftGhost: null, rightGhost: null };
    let sliders = [], last = null;
    let velocityScale = 1, massScale = 1;

    function request() {
      return {
        q: q.slice(), u: DIRECTIONS[tipDir.value], tipS: parseFloat(tipSlider.value),
        selfJoint: parseInt(selfJoint.value, 10), selfS: parseFloat(selfSlider.value),
      };
    }

    function select(key) {
      robot = robots.find((r) => r.key === key);
      robotMenu.value = key;
      caption.textContent = robot.caption;
      q = robot.q0.slice();
      jointsBox.replaceChildren();
      sliders = robot.joints.map((j, i) => {
        const row = el('div', { class: 'row' });
        const [lower, upper] = sliderRange(j, q[i]);
        const s = el('input', { type: 'range', id: `q${i}`, min: String(lower), max: String(upper), step: String((upper - lower) / 400), value: String(q[i]) });
        const value = el('span', { class: 'num' }, degrees(j, q[i]));
        s.addEventListener('input', () => { q[i] = parseFloat(s.value); value.textContent = degrees(j, q[i]); draw(); });
        row.append(el('span', {}, j.name), s, value);
        jointsBox.append(row);
        return s;
      });
      selfJoint.replaceChildren(...robot.joints.map((j, i) => el('option', { value: String(i) }, j.name)));
      selfJoint.value = String(robot.self_joint);
      selfSlider.value = '0';
      tipSlider.value = '0';
      for (const v of allViews) for (const k of ['robot', 'ghost']) if (v[k]) { v.scene.remove(v[k].root); v[k].dispose(); v[k] = null; }
      // Each copy is one mesh (scene.js): one draw call per arm, not one per shape.
      main.robot = buildMergedRobot(robot.scene, 1);
      left.ghost = buildMergedRobot(robot.scene, 0.25);
      left.robot = buildMergedRobot(robot.scene, 1);
      right.ghost = buildMergedRobot(robot.scene, 0.25);
      right.robot = buildMergedRobot(robot.scene, 1);
      for (const v of allViews) for (const k of ['robot', 'ghost']) if (v[k]) v.scene.add(v[k].root);
      // Scales fixed per robot at q0: the largest finite radius is drawn 0.25 m long.
      const v0 = core.view(robot.handle, request());
      velocityScale = 0.25 / Math.max(1e-9, ...v0.velocity.radii);
      massScale = 0.25 / Math.max(1e-9, ...v0.mass.radii.filter((r) => r !== null));
      // Frame the arm: the box of its body origins and tip at q0.
      const box = new THREE.Box3().expandByPoint(new THREE.Vector3(0, 0, 0)).expandByPoint(new THREE.Vector3(...v0.x));
      for (const p of v0.poses) box.expandByPoint(new THREE.Vector3(p[0], p[1], p[2]));
      const center = box.getCenter(new THREE.Vector3());
      const radius = Math.max(0.45, box.getSize(new THREE.Vector3()).length() / 2 + 0.3);
      resize();
      allViews.forEach((v) => v.frame(center, radius));
      draw();
    }

    function numbersText(v) {
      const f = (x) => (x === null ? '∞' : x.toPrecision(4));
      const lines = [
        `tip x = (${v.x.map((c) => c.toFixed(3)).join(', ')}) m`,
        `σ(Jv) = ${v.velocity.radii.map(f).join(', ')}   rank ${v.rank}`,
        `√m_u  = ${v.mass.radii.map(f).join(', ')} √kg`,
      ];
      if (v.singular.length === 0) lines.push('no singular direction: the tip moves every way');
      for (const s of v.singular) lines.push(`${TYPE_NAMES[s.type]}: u = (${s.u.map((c) => c.toFixed(3)).join(', ')})`);
      lines.push(`J+ moves q by   (${v.pseudo_inverse.q.map((c, i) => (c - q[i]).toFixed(3)).join(', ')})`);
      lines.push(`Jbar moves q by (${v.dynamically_consistent.q.map((c, i) => (c - q[i]).toFixed(3)).join(', ')})`);
      return lines.join('\n');
    }

    function draw() {
      const t0 = performance.now();
      const v = core.view(robot.handle, request());
      api.computeMs.push(performance.now() - t0);
      last = v;
      main.robot.pose(v.poses);
      left.ghost.pose(v.poses);
      right.ghost.pose(v.poses);
      left.robot.pose(v.pseudo_inverse.poses);
      right.robot.pose(v.dynamically_consistent.poses);
      // With both motion sliders at zero the faint arm at q lies inside the solid one: not drawn.
      const req = request();
      left.ghost.root.visible = right.ghost.root.visible = req.tipS !== 0 || req.selfS !== 0;
      const tip = new THREE.Vector3(...v.x);
      velocity.position.copy(tip);
      mass.position.copy(tip);
      placeEllipsoid(velocity, v.velocity.axes, v.velocity.radii, velocityScale, 0.35);
      placeEllipsoid(mass, v.mass.axes, v.mass.radii, massScale, 0.35);
      for (const a of arrows) { main.scene.remove(a); a.dispose(); }  // its geometry and materials
      arrows = v.singular.map((s) => {
        const a = new THREE.ArrowHelper(new THREE.Vector3(...s.u), tip, 0.3, new THREE.Color(TYPE_COLORS[s.type]), 0.06, 0.03);
        a.userData = { u: s.u, type: s.type, color: TYPE_COLORS[s.type] };
        // Drawn over the arm: a direction along a link (the 3R arm's Z0) would hide inside it.
        for (const part of [a.line, a.cone]) {
          part.material.depthTest = false;
          part.renderOrder = 1;
        }
        main.scene.add(a);
        return a;
      });
      numbers.textContent = numbersText(v);
      tipValue.textContent = `${parseFloat(tipSlider.value).toFixed(3)} m`;
      selfValue.textContent = degrees(robot.joints[parseInt(selfJoint.value, 10)], parseFloat(selfSlider.value));
      for (const view of allViews) view.render();
      // Reading a pixel back waits until the GPU process has drawn the frame (the test's timing).
      if (api.waitForGpu) renderer.getContext().readPixels(0, 0, 1, 1, 0x1908, 0x1401, new Uint8Array(4));
      api.redrawMs.push(performance.now() - t0);
    }

    for (const c of [tipDir, tipSlider, selfJoint, selfSlider]) c.addEventListener('input', draw);
    robotMenu.addEventListener('change', () => select(robotMenu.value));
    select(robots[0].key);

    // The test hook: the page's own numbers and controls.
    api.robots = robots.map((r) => r.key);
    api.select = (key) => select(key);
    api.view = () => last;
    api.compute = (key, req) => core.view(robots.find((r) => r.key === key).handle, req);
    api.setJoint = (i, value) => { sliders[i].value = String(value); sliders[i].dispatchEvent(new Event('input')); };
    api.setQ = (values) => { q = values.slice(); values.forEach((x, i) => { sliders[i].value = String(x); }); draw(); };
    api.arrows = () => arrows.map((a) => a.userData);
    api.setRobotVisible = (visible) => { main.robot.root.visible = visible; main.render(); };
    api.ready = true;
  });
}

try {
  const started = main();
  if (started) started.catch((e) => console.error(`opspace explorer: ${e.stack || e}`));
} catch (e) {
  console.error(`opspace explorer: ${e.stack || e}`);
}
