// The opspace live lab page (`PROGRAM ... --live`, docs/live.md). esbuild bundles this file with
// three.js into build/<preset>/web/opspace-live.js, which the program's HTTP server inlines into
// the page it serves at / after a <script id="opspace-live-data" type="application/json"> block:
// the robot's shapes, the control laws, gains, plots and markers. The page then follows the
// simulation through Server-Sent Events (/events, one JSON frame per message, about 60 a
// second) and sends the person's commands (pause, reset, speed, law, gains, pushes with the
// mouse) as JSON to POST /command. The protocol is in docs/live.md ("Protocol").
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { baseScene, buildRobot, el, setPose } from './scene.js';

// The test hook (web/test/check_live.mjs).
const api = {
  ready: false, stopped: false, frames: 0, lastFrame: null, latencies: [], fps: 0,
  samples: 0, plotDraws: 0, commandErrors: [], lastSent: 0, trace: null,
};
window.opspaceLive = api;

const SPEEDS = [0.1, 0.25, 0.5, 1];
const SIDE = 360;  // the width of the side panel, px
const PLOT_HEIGHT = 110;

const CSS = `
html, body { margin: 0; height: 100%; overflow: hidden; font: 13px system-ui, sans-serif; color: #1d2330; background: #f4f5f7; }
#stage { position: absolute; left: 0; top: 0; bottom: 0; right: ${SIDE}px; touch-action: none; }
#stage canvas { width: 100%; height: 100%; display: block; }
#hud { position: absolute; top: 8px; left: 10px; background: rgba(255,255,255,0.88); padding: 6px 10px; border-radius: 6px; max-width: 46%; }
#hud h1 { font-size: 15px; margin: 0 0 2px 0; }
#hud .sub { margin: 0 0 4px 0; color: #555; }
#readout { margin: 4px 0 0 0; font: 13px ui-monospace, monospace; white-space: pre; }
#legend { list-style: none; margin: 4px 0 0 0; padding: 0; font-size: 12px; }
.swatch { display: inline-block; width: 10px; height: 10px; margin-right: 6px; border-radius: 2px; }
#error { display: none; margin-top: 6px; padding: 6px 8px; border-radius: 4px; background: #c0392b; color: #fff; font-weight: 600; }
#error button { margin-left: 8px; }
#stopped { display: none; position: absolute; left: calc((100% - ${SIDE}px) / 2); bottom: 16px; transform: translateX(-50%); padding: 8px 14px; border-radius: 6px; background: #1d2330; color: #fff; font-weight: 600; }
#push-label { display: none; position: absolute; pointer-events: none; padding: 1px 6px; border-radius: 4px; background: rgba(255,255,255,0.9); border: 1px solid #d35400; color: #a04000; font: 600 13px ui-monospace, monospace; transform: translate(8px, -50%); }
#side { position: absolute; right: 0; top: 0; bottom: 0; width: ${SIDE}px; overflow-y: auto; padding: 8px 10px; box-sizing: border-box; background: #fff; border-left: 1px solid #d6d8de; }
#side h2 { font-size: 13px; margin: 10px 0 4px 0; }
#side p { margin: 4px 0; color: #555; line-height: 1.35; }
.buttons { display: flex; gap: 6px; align-items: center; flex-wrap: wrap; }
.row { display: grid; grid-template-columns: 96px 1fr 64px; gap: 6px; align-items: center; margin: 2px 0; }
.row input[type=range], .row select { width: 100%; }
.num { font: 12px ui-monospace, monospace; text-align: right; }
#status { min-height: 1.3em; font-size: 12px; color: #555; }
#status.bad { color: #c0392b; font-weight: 600; }
.plot { margin: 6px 0; }
.plot .title { font-weight: 600; }
.plot .keys { font-size: 11px; color: #444; }
.plot .keys span { margin-right: 10px; white-space: nowrap; }
.plot canvas { display: block; width: 100%; height: ${PLOT_HEIGHT}px; background: #fafbfc; border: 1px solid #e1e3e8; border-radius: 3px; box-sizing: border-box; }
#no-webgl { padding: 2em; }
`;

const number = (v, digits = 3) => (Number.isFinite(v) ? v.toFixed(digits) : '-');
const trimmed = (v) => (Number.isFinite(v) ? String(Number(v.toPrecision(4))) : '-');

// ------------------------------------------------------------------------------------------
// Commands: POST /command, one request at a time (the server then applies them in the order
// sent), ids increasing. A push or a gain replaces a queued one of its kind: the latest wins.

function commandQueue(onError) {
  const queue = [];
  const sentAt = new Map();  // id -> performance.now() when sent, until a frame acknowledges it
  let busy = false, nextId = 1, lastPush = 0, timer = 0;
  async function pump() {
    if (busy || !queue.length || api.stopped) return;
    const item = queue[0];
    if (item.key === 'push') {  // at most about 60 pushes a second
      const wait = lastPush + 16 - performance.now();
      if (wait > 0) {
        if (!timer) timer = setTimeout(() => { timer = 0; pump(); }, wait);
        return;
      }
      lastPush = performance.now();
    }
    queue.shift();
    busy = true;
    const id = nextId++;
    const body = { id, ...item.body };
    api.lastSent = id;
    item.sent?.(id);
    sentAt.set(id, performance.now());
    try {
      const r = await fetch('/command', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) });
      if (!r.ok) {
        sentAt.delete(id);
        let why = `${r.status} ${r.statusText}`;
        try { why = (await r.json()).error || why; } catch { /* not JSON */ }
        item.refused?.();
        onError(`${body.command}: ${why}`);
      }
    } catch (e) {
      sentAt.delete(id);
      item.refused?.();
      if (!api.stopped) onError(`${body.command}: the program did not answer (${e.message})`);
    }
    busy = false;
    pump();
  }
  return {
    /// Queues `body` (a command without its id). `key`: replaces a queued command with the same
    /// key. `sent(id)` is called when it goes, `refused()` when the server refuses it.
    send(body, { key = null, sent = null, refused = null } = {}) {
      const queued = key && queue.find((c) => c.key === key);
      if (queued) Object.assign(queued, { body, sent, refused });
      else queue.push({ body, key, sent, refused });
      pump();
    },
    drop(key) {
      for (let i = queue.length - 1; i >= 0; --i) if (queue[i].key === key) queue.splice(i, 1);
    },
    /// A frame has applied every command up to `id`: their latencies.
    acknowledged(id, now) {
      for (const [sent, at] of sentAt) {
        if (sent > id) continue;
        api.latencies.push(now - at);
        if (api.latencies.length > 1000) api.latencies.shift();
        sentAt.delete(sent);
      }
    },
  };
}

// ------------------------------------------------------------------------------------------
// Plots: the samples of the last `window` seconds, one small canvas per plot.

function buildPlots(data, parent) {
  const window_ = data.window || 10;
  const plots = [];
  let column = 1;  // samples are [t, values of plot 0's series, plot 1's, ...]
  for (const p of data.plots || []) {
    const box = el('div', { class: 'plot' });
    box.append(el('div', { class: 'title' }, p.unit ? `${p.title} (${p.unit})` : p.title));
    const keys = el('div', { class: 'keys' });
    for (const s of p.series) {
      const key = el('span');
      key.append(el('span', { class: 'swatch', style: `background:${s.color}` }), document.createTextNode(s.label));
      keys.append(key);
    }
    const canvas = el('canvas');
    box.append(keys, canvas);
    parent.append(box);
    plots.push({ ...p, canvas, first: column });
    column += p.series.length;
  }
  let rows = [];
  const minStep = window_ / 1500;  // thinning: more points than pixels are not drawn anyway
  function add(samples) {
    for (const s of samples) {
      const last = rows[rows.length - 1];
      if (last && s[0] >= last[0] && s[0] - last[0] < minStep) continue;
      rows.push(s);
      api.samples += 1;
    }
    const end = rows.length ? rows[rows.length - 1][0] : 0;
    let drop = 0;
    while (drop < rows.length && rows[drop][0] < end - window_ - minStep) ++drop;
    if (drop) rows = rows.slice(drop);
  }
  function clear() { rows = []; }
  function draw(t) {
    const end = Math.max(window_, t), start = end - window_;
    for (const p of plots) {
      const ratio = window.devicePixelRatio || 1;
      const w = Math.max(1, Math.round(p.canvas.clientWidth * ratio)), h = Math.max(1, Math.round(p.canvas.clientHeight * ratio));
      if (p.canvas.width !== w || p.canvas.height !== h) { p.canvas.width = w; p.canvas.height = h; }
      const ctx = p.canvas.getContext('2d');
      ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
      const W = w / ratio, H = h / ratio;
      ctx.clearRect(0, 0, W, H);
      let lo = Infinity, hi = -Infinity;
      for (const r of rows) {
        if (r[0] < start) continue;
        for (let k = 0; k < p.series.length; ++k) {
          const v = r[p.first + k];
          if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
        }
      }
      if (!(hi >= lo)) { lo = -1; hi = 1; }
      const pad = Math.max((hi - lo) * 0.08, Math.abs(hi) * 1e-3, 1e-9);
      lo -= pad; hi += pad;
      const left = 48, right = 6, top = 6, bottom = 16;
      const x = (s) => left + ((s - start) / window_) * (W - left - right);
      const y = (v) => top + ((hi - v) / (hi - lo)) * (H - top - bottom);
      ctx.strokeStyle = '#e1e3e8';
      ctx.lineWidth = 1;
      ctx.beginPath();
      for (const v of [lo + pad, hi - pad]) { ctx.moveTo(left, y(v)); ctx.lineTo(W - right, y(v)); }
      ctx.stroke();
      ctx.fillStyle = '#666';
      ctx.font = '10px ui-monospace, monospace';
      ctx.textAlign = 'right';
      ctx.textBaseline = 'middle';
      ctx.fillText(trimmed(hi - pad), left - 4, y(hi - pad));
      ctx.fillText(trimmed(lo + pad), left - 4, y(lo + pad));
      ctx.textBaseline = 'bottom';
      ctx.fillText(`${number(end, 1)} s`, W - right, H);
      ctx.textAlign = 'left';
      ctx.fillText(`${number(start, 1)} s`, left, H);
      ctx.save();
      ctx.beginPath();
      ctx.rect(left, 0, W - left - right, H - bottom);
      ctx.clip();
      ctx.lineWidth = 1.5;
      for (let k = p.series.length - 1; k >= 0; --k) {  // the first series on top
        ctx.strokeStyle = p.series[k].color;
        ctx.beginPath();
        let pen = false;
        for (const r of rows) {
          if (r[0] < start - minStep) continue;
          const v = r[p.first + k];
          if (!Number.isFinite(v)) { pen = false; continue; }
          if (pen) ctx.lineTo(x(r[0]), y(v)); else ctx.moveTo(x(r[0]), y(v));
          pen = true;
        }
        ctx.stroke();
      }
      ctx.restore();
    }
    api.plotDraws += 1;
  }
  return { add, clear, draw };
}

// ------------------------------------------------------------------------------------------

function main() {
  const data = JSON.parse(document.getElementById('opspace-live-data').textContent);
  api.data = data;
  document.title = `${data.title} (live)`;
  document.head.append(el('style', {}, CSS));
  // No icon: otherwise Chromium asks the server for /favicon.ico.
  document.head.append(el('link', { rel: 'icon', href: 'data:,' }));
  const laws = data.laws || [];
  const gains = data.gains || [];

  // The stage, with the head-up panel over it.
  const stage = el('div', { id: 'stage' });
  const hud = el('div', { id: 'hud' });
  hud.append(el('h1', {}, data.title));
  if (data.subtitle) hud.append(el('p', { class: 'sub' }, data.subtitle));
  const readout = el('div', { id: 'readout' });
  readout.textContent = 't = 0.000 s   real time x0.00\nconnecting...';
  hud.append(readout);
  const legend = el('ul', { id: 'legend' });
  for (const m of data.markers || []) {
    const li = el('li');
    li.append(el('span', { class: 'swatch', style: `background:${m.color}` }), document.createTextNode(m.label || m.name));
    legend.append(li);
  }
  hud.append(legend);
  const errorBox = el('div', { id: 'error' });
  const errorText = el('span', { id: 'error-text' });
  const errorReset = el('button', { id: 'error-reset', type: 'button' }, 'Reset');
  errorBox.append(errorText, errorReset);
  hud.append(errorBox);
  const stopped = el('div', { id: 'stopped' }, 'the program has stopped: run it again and reload this page');
  const pushLabel = el('div', { id: 'push-label' });

  // The side panel: controls, then the plots.
  const side = el('div', { id: 'side' });
  const buttons = el('div', { class: 'buttons' });
  const pause = el('button', { id: 'pause', type: 'button' }, 'Pause');
  const reset = el('button', { id: 'reset', type: 'button' }, 'Reset');
  const speed = el('select', { id: 'speed', title: 'simulated seconds per wall-clock second' });
  for (const s of SPEEDS) speed.append(el('option', { value: String(s) }, `${s}x`));
  speed.value = '1';
  buttons.append(pause, reset, el('span', {}, 'speed'), speed);
  side.append(buttons);
  let law = null;
  if (laws.length > 1) {
    const row = el('div', { class: 'row' });
    law = el('select', { id: 'law' });
    laws.forEach((name, i) => law.append(el('option', { value: String(i) }, name)));
    law.value = String(data.law || 0);
    row.append(el('span', {}, 'control law'), law, el('span'));
    row.style.gridTemplateColumns = '96px 1fr';
    side.append(row);
  }
  const sliders = {};
  if (gains.length) side.append(el('h2', {}, 'gains'));
  for (const g of gains) {
    const row = el('div', { class: 'row' });
    const input = el('input', { id: `gain-${g.name}`, type: 'range', min: String(g.min), max: String(g.max), step: 'any', value: String(g.value) });
    const shown = el('span', { class: 'num' }, trimmed(g.value));
    row.append(el('span', { title: g.name }, g.label || g.name), input, shown);
    side.append(row);
    sliders[g.name] = { input, shown, held: false, pending: 0 };
  }
  const status = el('div', { id: 'status' });
  side.append(status, el('p', {}, 'Drag the arm to pull it with a spring; drag elsewhere to turn the view, wheel to zoom.'));
  const plots = buildPlots(data, side);
  document.body.append(stage, hud, stopped, pushLabel, side);

  function say(text, bad = false) {
    status.textContent = text;
    status.className = bad ? 'bad' : '';
  }
  const commands = commandQueue((why) => { api.commandErrors.push(why); say(`refused: ${why}`, true); });

  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  } catch (e) {
    stage.append(el('p', { id: 'no-webgl' }, 'This browser could not create a WebGL context: the arm cannot be drawn (the plots and controls still work).'));
    console.warn(`opspace live: WebGL unavailable: ${e.message}`);
  }
  const scene = baseScene();
  const robot = buildRobot(data, 1);
  scene.add(robot.root);
  const markers = {};
  for (const m of data.markers || []) {
    const mesh = new THREE.Mesh(new THREE.SphereGeometry(m.radius || 0.02, 20, 14),
      new THREE.MeshBasicMaterial({ color: new THREE.Color(m.color), transparent: true, opacity: 0.8 }));
    mesh.visible = false;
    scene.add(mesh);
    markers[m.name] = mesh;
  }
  // The push: a spring from the pulled point to the mouse's point, and a ball at the mouse.
  const springGeometry = new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3()]);
  const spring = new THREE.Line(springGeometry, new THREE.LineBasicMaterial({ color: 0xd35400 }));
  const handle = new THREE.Mesh(new THREE.SphereGeometry(0.012, 16, 10), new THREE.MeshBasicMaterial({ color: 0xd35400 }));
  spring.visible = handle.visible = false;
  scene.add(spring, handle);

  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  camera.up.set(0, 0, 1);
  const view = new THREE.Vector3(...(data.view || [1, -1, 0.7])).normalize();
  camera.position.copy(view).multiplyScalar(3);
  const canvas = renderer ? renderer.domElement : el('canvas');
  if (renderer) {
    renderer.setPixelRatio(window.devicePixelRatio);
    stage.append(canvas);
  }

  // As the replay page: the scene is framed in the larger free area beside or below the panel.
  function freeArea(w, h) {
    const right = hud.offsetLeft + hud.offsetWidth + 8, bottom = hud.offsetTop + hud.offsetHeight + 8;
    const beside = { x: right, y: 0, w: Math.max(1, w - right), h };
    const below = { x: 0, y: bottom, w, h: Math.max(1, h - bottom) };
    const size = (a) => Math.min(a.w, a.h);
    return size(beside) >= size(below) ? beside : below;
  }
  const stageSize = () => [stage.clientWidth || window.innerWidth - SIDE, stage.clientHeight || window.innerHeight];
  function resize() {
    const [w, h] = stageSize();
    if (renderer) renderer.setSize(w, h, false);
    camera.aspect = w / h;
    const area = freeArea(w, h);
    camera.setViewOffset(w, h, w / 2 - (area.x + area.w / 2), h / 2 - (area.y + area.h / 2), w, h);
    camera.updateProjectionMatrix();
  }
  /// Frames the arm as it stands at the first frame, with room for it to move: the box around
  /// its shapes, its markers and the base, grown by half.
  function frameView() {
    robot.root.updateMatrixWorld(true);
    const box = new THREE.Box3().setFromObject(robot.root);
    for (const m of Object.values(markers)) if (m.visible) box.expandByPoint(m.position);
    box.expandByPoint(new THREE.Vector3(0, 0, 0));
    const center = box.getCenter(new THREE.Vector3());
    const radius = Math.max(0.3, box.getSize(new THREE.Vector3()).length() / 2) * 1.2;
    const [w, h] = stageSize();
    const area = freeArea(w, h);
    const shrink = Math.max(1, h / 1.45 / Math.min(area.w, area.h));
    camera.position.copy(center).addScaledVector(view, (radius / Math.tan((20 * Math.PI) / 180)) * 1.45 * shrink);
    controls.target.copy(center);
    controls.update();
  }

  // Pushing: pointerdown on the arm picks a body and a point of it. This listener is added
  // before OrbitControls' own, so that it can turn them off before they start turning the view.
  const raycaster = new THREE.Raycaster();
  let shown = null;  // the frame drawn
  let drag = null;  // { body, local: the point in the body's frame, plane, pointerId }
  function ray(event) {
    const r = canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    return raycaster;
  }
  function bodyOf(object) {
    for (let o = object; o; o = o.parent) {
      const i = robot.bodies.indexOf(o);
      if (i >= 0) return i;
    }
    return -1;
  }
  function pick(event) {
    const hits = ray(event).intersectObject(robot.root, true);  // the base hides what is behind it
    return hits.length ? { body: bodyOf(hits[0].object), point: hits[0].point } : null;
  }
  function sendPush() {
    if (!drag) return;
    commands.send({ command: 'push', body: drag.body, point: drag.local, target: drag.target.toArray() }, { key: 'push' });
  }
  canvas.addEventListener('pointerdown', (event) => {
    if (event.button !== 0 || drag || !shown || api.stopped) return;
    const hit = pick(event);
    if (!hit || hit.body < 0) return;
    // The body's pose as drawn, which the hit point is on (the last frame received may be newer).
    const p = shown.poses, o = 7 * hit.body;
    const turn = new THREE.Quaternion(p[o + 3], p[o + 4], p[o + 5], p[o + 6]).invert();
    const local = hit.point.clone().sub(new THREE.Vector3(p[o], p[o + 1], p[o + 2])).applyQuaternion(turn);
    const normal = camera.getWorldDirection(new THREE.Vector3());
    drag = {
      body: hit.body, local: local.toArray(), plane: new THREE.Plane().setFromNormalAndCoplanarPoint(normal, hit.point),
      target: hit.point.clone(), pointerId: event.pointerId,
    };
    controls.enabled = false;
    canvas.setPointerCapture(event.pointerId);
    canvas.style.cursor = 'grabbing';
    sendPush();
    event.preventDefault();
  });
  canvas.addEventListener('pointermove', (event) => {
    if (!drag) {
      if (event.buttons === 0 && shown) {
        const hit = pick(event);
        canvas.style.cursor = hit && hit.body >= 0 ? 'grab' : '';
      }
      return;
    }
    if (event.pointerId !== drag.pointerId) return;
    if (ray(event).ray.intersectPlane(drag.plane, drag.target)) sendPush();
  });
  function release(event) {
    if (!drag || (event && event.pointerId !== drag.pointerId)) return;
    drag = null;
    controls.enabled = true;
    canvas.style.cursor = '';
    commands.drop('push');
    commands.send({ command: 'release' });
  }
  for (const type of ['pointerup', 'pointercancel', 'lostpointercapture']) canvas.addEventListener(type, release);
  window.addEventListener('blur', () => release());

  const controls = new OrbitControls(camera, canvas);
  window.addEventListener('resize', resize);
  resize();
  controls.update();

  // The controls: each shows the server's value from the frames, except while the person holds
  // it or until the frames have applied the command it sent (`pending`: its id, Infinity while
  // queued).
  const speedState = { pending: 0 }, lawState = { pending: 0 };
  const tracked = (state) => ({
    sent: (id) => { state.pending = id; },
    refused: () => { state.pending = 0; },
  });
  const settled = (state, frame) => frame.command >= state.pending;
  pause.addEventListener('click', () => {
    const f = api.lastFrame;
    commands.send({ command: f && f.paused ? 'resume' : 'pause' });
  });
  const doReset = () => commands.send({ command: 'reset' });
  reset.addEventListener('click', doReset);
  errorReset.addEventListener('click', doReset);
  speed.addEventListener('change', () => {
    speedState.pending = Infinity;
    commands.send({ command: 'speed', value: Number(speed.value) }, { key: 'speed', ...tracked(speedState) });
  });
  if (law) {
    law.addEventListener('change', () => {
      lawState.pending = Infinity;
      commands.send({ command: 'law', value: Number(law.value) }, { key: 'law', ...tracked(lawState) });
    });
  }
  for (const [name, s] of Object.entries(sliders)) {
    s.input.addEventListener('pointerdown', () => { s.held = true; });
    s.input.addEventListener('pointerup', () => { s.held = false; });
    s.input.addEventListener('input', () => {
      s.pending = Infinity;
      s.shown.textContent = trimmed(Number(s.input.value));
      commands.send({ command: 'gain', name, value: Number(s.input.value) }, { key: `gain ${name}`, ...tracked(s) });
    });
  }
  window.addEventListener('keydown', (e) => {
    if (e.key === ' ' && e.target === document.body) { pause.click(); e.preventDefault(); }
  });

  // The frames.
  let framed = false, fresh = false, plotsDirty = true, lastPlotDraw = 0, lastT = -Infinity;
  const arrivals = [];
  function show(frame) {
    const p = frame.poses;
    if (p && p.length >= 7 * data.bodies) for (let i = 0; i < data.bodies; ++i) setPose(robot.bodies[i], p, 7 * i);
    for (const [name, mesh] of Object.entries(markers)) {
      const at = frame.markers && frame.markers[name];
      mesh.visible = Array.isArray(at) && at.length === 3;
      if (mesh.visible) mesh.position.set(at[0], at[1], at[2]);
    }
    const push = frame.push;
    spring.visible = handle.visible = !!push;
    if (push) {
      springGeometry.attributes.position.setXYZ(0, ...push.point);
      springGeometry.attributes.position.setXYZ(1, ...push.target);
      springGeometry.attributes.position.needsUpdate = true;
      springGeometry.computeBoundingSphere();
      handle.position.set(...push.target);
    }
    const lawName = laws[frame.law] !== undefined ? laws[frame.law] : `law ${frame.law}`;
    const latency = api.latencies.length ? `   command ${api.latencies[api.latencies.length - 1].toFixed(0)} ms` : '';
    readout.textContent = `t = ${number(frame.t)} s   real time x${number(frame.rtf, 2)}${frame.paused ? '   PAUSED' : ''}\n` +
      `${laws.length ? lawName : ''}${latency}`;
    errorBox.style.display = frame.error ? 'block' : 'none';
    errorText.textContent = frame.error ? `stopped: ${frame.error}` : '';
    pause.textContent = frame.paused ? 'Resume' : 'Pause';
    if (settled(speedState, frame) && Number.isFinite(frame.speed)) {
      const nearest = SPEEDS.reduce((a, b) => (Math.abs(b - frame.speed) < Math.abs(a - frame.speed) ? b : a));
      speed.value = String(nearest);
    }
    if (law && settled(lawState, frame)) law.value = String(frame.law);
    for (const [name, s] of Object.entries(sliders)) {
      const v = frame.gains && frame.gains[name];
      if (!Number.isFinite(v) || s.held || !settled(s, frame)) continue;
      s.input.value = String(v);
      s.shown.textContent = trimmed(v);
    }
  }
  function placePushLabel() {
    const push = api.lastFrame && api.lastFrame.push;
    if (!push) { pushLabel.style.display = 'none'; return; }
    const at = new THREE.Vector3(...push.target).project(camera);
    const r = canvas.getBoundingClientRect();
    const f = push.force || [0, 0, 0];
    pushLabel.textContent = `${Math.hypot(f[0], f[1], f[2]).toFixed(1)} N`;
    pushLabel.style.left = `${r.left + ((at.x + 1) / 2) * r.width}px`;
    pushLabel.style.top = `${r.top + ((1 - at.y) / 2) * r.height}px`;
    pushLabel.style.display = 'block';
  }

  const source = new EventSource('/events');
  let silence = 0;
  source.onmessage = (message) => {
    let frame;
    try {
      frame = JSON.parse(message.data);
    } catch (e) {
      console.error(`opspace live: a frame that is not JSON: ${message.data.slice(0, 80)}`);
      return;
    }
    const now = performance.now();
    clearTimeout(silence);
    silence = 0;
    if (frame.t < lastT - 1e-9) plots.clear();  // a reset: the run starts again at t = 0
    lastT = frame.t;
    api.frames += 1;
    api.lastFrame = frame;
    if (api.trace) api.trace.push(frame);  // the test's record (check_live.mjs)
    arrivals.push(now);
    while (arrivals.length && arrivals[0] < now - 1000) arrivals.shift();
    api.fps = arrivals.length;
    if (Number.isFinite(frame.command)) commands.acknowledged(frame.command, now);
    if (frame.samples && frame.samples.length) { plots.add(frame.samples); plotsDirty = true; }
    fresh = true;
  };
  // The stream ends when the program exits: EventSource would try to reconnect, so after an
  // error with no frame for 2 s the page closes it and says so.
  source.onerror = () => {
    if (api.stopped || silence) return;
    silence = setTimeout(() => {
      source.close();
      api.stopped = true;
      release();
      stopped.style.display = 'block';
      pushLabel.style.display = 'none';
      for (const c of side.querySelectorAll('button, select, input')) c.disabled = true;
      errorReset.disabled = true;
      say('the program has stopped');
    }, source.readyState === EventSource.CLOSED ? 0 : 2000);
  };

  function render() {
    if (renderer) renderer.render(scene, camera);
  }
  function tick(now) {
    if (fresh && api.lastFrame) {
      fresh = false;
      shown = api.lastFrame;
      show(shown);
      if (!framed) {
        framed = true;
        frameView();
      }
      placePushLabel();
      if (!api.ready) {
        api.ready = true;
        say('connected');
      }
    }
    if (plotsDirty && now - lastPlotDraw > 50) {  // plots at 20 Hz: the eye does not need more
      plotsDirty = false;
      lastPlotDraw = now;
      plots.draw(api.lastFrame ? api.lastFrame.t : 0);
    }
    while (arrivals.length && arrivals[0] < now - 1000) arrivals.shift();
    api.fps = arrivals.length;
    controls.update();
    render();
    if (!api.stopped) placePushLabel();
    requestAnimationFrame(tick);
  }
  render();
  plots.draw(0);
  requestAnimationFrame(tick);

  /// The pixel (CSS, page coordinates) where body i's origin is drawn.
  api.screenOf = (i) => {
    const p = shown.poses;
    const at = new THREE.Vector3(p[7 * i], p[7 * i + 1], p[7 * i + 2]).project(camera);
    const r = canvas.getBoundingClientRect();
    return { x: r.left + ((at.x + 1) / 2) * r.width, y: r.top + ((1 - at.y) / 2) * r.height };
  };
  /// The body drawn at a pixel (page coordinates): its index, -1 for the base, null for none.
  api.bodyAt = (x, y) => {
    const hit = pick({ clientX: x, clientY: y });
    return hit ? hit.body : null;
  };
  api.send = (body) => commands.send(body);
  api.render = render;
}

try {
  main();
} catch (e) {
  console.error(`opspace live: ${e.stack || e}`);
}
