// Runs a problem program's live lab (`PROGRAM ARG... --live --port 0`, docs/live.md), opens the
// page it serves in Debian's headless Chromium (driven by playwright-core) and uses it as a
// person would:
//   node check_live.mjs PROGRAM SCREENSHOT.png [ARG...]
// Checks: the page connects; 20 frames or more a second arrive and simulated time advances;
// the arm's pixels change; reset brings t back near 0 and the start pose (and the gains back);
// a mouse drag on body 2 (the PUMA's forearm, at the elbow) pulls it with a force shown in
// newtons and moves it away from where the same run goes unpushed; pause holds t and the pose;
// the law switch reaches the frames and the plots keep drawing; problem 1b's page says what the
// physics does (its note), shows the measured tip offset beside the one predicted for the push,
// and draws the reference's tip as a ghost that follows the law; the run waited for the page
// (its first frame at t = 0); the subtitle shows the measured tip error and no promise; every
// plot label lies inside its canvas, also for the widest labels; a refused command is shown; no
// console errors; SIGINT ends the program with status 0 within 3 s, its port closed, and the
// page says that it has stopped. The screenshot is taken during the drag.
// Exit 0: all passed; 1: a check failed; 77: Chromium or playwright-core is missing (ctest
// SKIP; under CI=1 that fails instead), or the program was built without the live page.
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';

const [program, screenshot, ...programArgs] = process.argv.slice(2);
if (!program || !screenshot) {
  console.error('usage: node check_live.mjs PROGRAM SCREENSHOT.png [ARG...]');
  process.exit(2);
}
let cleanUp = () => {};
function skip(why) {
  cleanUp();
  if (process.env.CI) {
    console.log(`FAIL ${why} (CI is set: scripts/setup.sh should have installed it)`);
    process.exit(1);
  }
  console.log(`SKIP: ${why}`);
  process.exit(77);
}
if (!existsSync(process.env.CHROMIUM || '/usr/bin/chromium')) skip('Chromium is not installed (apt-get install chromium)');
let helpers;
try {
  helpers = await import('./chromium.mjs');
} catch (e) {
  skip(`playwright-core is not installed here (the build's npm ci failed?): ${e.message}`);
}
const { check, failures } = helpers.checker();
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const BODY = 2;  // hw2-p1's PUMA: body 2 is the forearm, its origin the elbow
// The push starts after this simulated time: until then the run after the first reset is
// unpushed, to compare with the run after the second (frames after a reset can be late on a
// busy machine: the first one is allowed up to 1 s).
const PUSH_FROM = 1;

// The program, in a folder of its own: its default outputs go there, not to the repository.
const work = mkdtempSync(path.join(os.tmpdir(), 'opspace-check-live-'));
cleanUp = () => rmSync(work, { recursive: true, force: true });
const args = [...programArgs, '--live', '--port', '0'];
mkdirSync(path.dirname(path.resolve(screenshot)), { recursive: true });
const child = spawn(program, args, { cwd: work, env: { ...process.env, OPSPACE_OUT: path.join(work, 'out') }, stdio: ['ignore', 'pipe', 'pipe'] });
let output = '';
let exited = null;  // { code, signal } once it has exited
const exit = new Promise((resolve) => child.on('exit', (code, signal) => { exited = { code, signal }; resolve(exited); }));
child.stdout.on('data', (d) => { output += d; });
child.stderr.on('data', (d) => { output += d; });
const printOutput = () => console.log(`--- ${path.basename(program)} ${args.join(' ')} said:\n${output.trimEnd()}\n---`);

async function liveUrl() {
  const deadline = Date.now() + 60000;
  while (Date.now() < deadline) {
    const m = output.match(/^live: (http:\/\/127\.0\.0\.1:(\d+)\/)\s*$/m);
    if (m) return { url: m[1], port: Number(m[2]) };
    if (exited) break;
    await sleep(50);
  }
  return null;
}
const portClosed = (port) => new Promise((resolve) => {
  const socket = net.connect({ host: '127.0.0.1', port });
  socket.on('connect', () => { socket.destroy(); resolve(false); });
  socket.on('error', () => resolve(true));
});

let browser = null;
try {
  const live = await liveUrl();
  if (!live) {
    if (exited && /^note:.*live/im.test(output)) {
      printOutput();
      skip('the program was built without the live page (see its note above)');
    }
    check(false, `the program printed 'live: http://127.0.0.1:PORT/' (it ${exited ? `exited with ${exited.code ?? exited.signal}` : 'did not, in 60 s'})`);
    throw new Error('no live URL');
  }
  console.log(`live page: ${live.url}`);
  browser = await helpers.launch();
  const { page, errors } = await helpers.openPage(browser, { width: 1280, height: 800 });
  await helpers.definePixelTools(page);
  await page.goto(live.url);
  const ready = await page.waitForFunction(() => window.opspaceLive && window.opspaceLive.ready, null, { timeout: 30000 })
    .then(() => true, () => false);
  check(ready, 'the page connects to the event stream and draws its first frame');
  if (!ready) throw new Error('not ready');
  const data = await page.evaluate(() => window.opspaceLive.data);
  // The program waited for the page (issue 46): the first frame it got is at the run's start,
  // although the browser opened it seconds after the address was printed.
  const firstT = await page.evaluate(() => window.opspaceLive.firstFrame.t);
  check(firstT < 0.1 && /waiting for the page at/.test(output),
    `the run waited for the page: its first frame is at t = ${firstT.toFixed(3)} s (< 0.1 s), and the program said it waits`);
  const frame = () => page.evaluate(() => window.opspaceLive.lastFrame);
  const state = () => page.evaluate(() => { const a = window.opspaceLive; return { frames: a.frames, t: a.lastFrame.t, fps: a.fps }; });
  /// Waits for a frame that satisfies `test` (a function of the frame, run in the page).
  const frameWhere = (test, timeout = 5000) => page.waitForFunction(
    (source) => { const f = window.opspaceLive.lastFrame; return f && new Function('f', `return (${source})(f)`)(f) ? f : null; },
    test.toString(), { timeout, polling: 'raf' }).then((h) => h.jsonValue(), () => null);
  /// Sends nothing itself: waits for the frames to apply the page's last command.
  const applied = () => frameWhere(new Function('f', 'return f.command >= window.opspaceLive.lastSent'));

  // Problem 1b's page: its note, the ghost's paths (one per law) and its legend entry. The checks
  // of the note, the ghost and the offsets were seen to fail (5 of them) with a bundle built
  // without the note, drawing the ghost of the next law and no predicted value
  // (OPSPACE_LIVE_VIEWER pointing at it): 8.2 mm from the tip, law 1 for 0, NaN mm.
  const note = await page.locator('#note').textContent().catch(() => '');
  check(/Jv A\^-1 Je\^T F \/ kpx/.test(note), `the page says what a push does to the tip: '${note.slice(0, 90)}...'`);
  const ghost = data.ghost;
  check(ghost && ghost.paths.length === data.laws.length && ghost.paths.every((p) => p.length >= 6 && p.length % 3 === 0) &&
    (await page.locator('#ghost-key').isVisible()),
    `the page has the reference's tip path for each of its ${data.laws.length} laws (${ghost ? ghost.paths.map((p) => p.length / 3).join(', ') : 'none'} points) and a legend entry for it`);

  // Frames: rate and simulated time.
  const a = await state();
  await sleep(2000);
  const b = await state();
  const rate = (b.frames - a.frames) / 2;
  check(rate >= 20, `${rate.toFixed(1)} frames a second arrive over 2 s (>= 20; the page measures ${b.fps})`);
  check(b.t - a.t > 0.3, `simulated time advances: ${a.t.toFixed(3)} s -> ${b.t.toFixed(3)} s in 2 s of wall clock (> 0.3 s)`);
  const f0 = await frame();
  check(f0.error === '', `the run has no error${f0.error ? `: ${f0.error}` : ''}`);
  check(Array.isArray(f0.poses) && f0.poses.length === 7 * data.bodies, `frames carry 7 x ${data.bodies} pose numbers (${f0.poses && f0.poses.length})`);

  // The arm's pixels change (WebGL only: the panels are HTML).
  // Three pictures 0.75 s apart, compared in the page: the arm is seen moving between two of
  // them (a swinging arm can pass through the same pose twice).
  const { changed, pixels } = await page.evaluate(async () => {
    const canvas = document.querySelector('#stage canvas');
    const grab = () => window.opspaceTest.pixels(canvas);
    const pictures = [grab()];
    for (let k = 0; k < 2; ++k) {
      await new Promise((resolve) => setTimeout(resolve, 750));
      pictures.push(grab());
    }
    let most = 0;
    for (const [a, b] of [[0, 1], [1, 2], [0, 2]]) {
      const p = pictures[a], q = pictures[b];
      let n = 0;
      for (let i = 0; i < p.length / 4; ++i) if (window.opspaceTest.differs(p, q, i)) ++n;
      most = Math.max(most, n);
    }
    return { changed: most, pixels: pictures[0].length / 4 };
  });
  const share = changed / pixels;
  check(share > 0.001, `${(100 * share).toFixed(2)} % of the view's pixels change between two of three pictures 0.75 s apart as the arm moves (> 0.1 %)`);

  // A gain moved, then reset: t back near 0, the start pose, the gains back to their values.
  if (data.gains.length) {
    const g = data.gains[0];
    const value = g.min + 0.75 * (g.max - g.min) === g.value ? g.min + 0.25 * (g.max - g.min) : g.min + 0.75 * (g.max - g.min);
    await page.evaluate(([name, v]) => {
      const input = document.getElementById(`gain-${name}`);
      input.value = String(v);
      input.dispatchEvent(new Event('input'));
    }, [g.name, value]);
    const f = await applied();
    check(f && Math.abs(f.gains[g.name] - value) <= 1e-6 * Math.max(1, Math.abs(value)),
      `the ${g.name} slider sets the gain (${f && f.gains[g.name]}, sent ${value})`);
  } else {
    console.log('note: the program shows no gains: the gain sliders are not checked');
  }
  const resetRun = async () => {
    await page.evaluate(() => { window.opspaceLive.trace = []; });
    await page.locator('#reset').click();
    if (!(await applied())) return null;
    // The first frame that applied it (the page may have drawn later ones by now).
    return page.evaluate(() => {
      const api = window.opspaceLive;
      api.resetId = api.lastSent;
      return api.trace.find((f) => f.command >= api.resetId);
    });
  };
  const before = await frame();
  const r1 = await resetRun();
  check(r1 && r1.t < 1, `reset: the first frame after it is at t = ${r1 && r1.t.toFixed(3)} s (< 1 s, from ${before.t.toFixed(1)} s)`);
  if (data.gains.length) {
    const g = data.gains[0];
    const slider = await page.locator(`#gain-${g.name}`).inputValue();
    check(r1 && r1.gains[g.name] === g.value && Math.abs(Number(slider) - g.value) <= (g.max - g.min) / 400,
      `reset: ${g.name} back to ${g.value} in the frames (${r1 && r1.gains[g.name]}) and on its slider (${slider})`);
  }
  const moved = (p, q, i) => Math.hypot(p[7 * i] - q[7 * i], p[7 * i + 1] - q[7 * i + 1], p[7 * i + 2] - q[7 * i + 2]);
  const elapsed = (since) => `${((Date.now() - since) / 1000).toFixed(1)} s`;

  // The drag, in the run that began at the reset: press on body 2 near its origin (the elbow)
  // and pull up and right by 150 px.
  await frameWhere(new Function('f', `return f.t > ${PUSH_FROM}`), 20000);
  // Unpushed, this program (the reference, PART3) runs the reference's own run, which the ghost
  // draws: its ball is where the tip is. Its points, every 20 ms, are that run's tip to 1e-9 m;
  // between them the chord errs by at most |ddx| h^2 / 8, with |ddx| <= 17^2 x 2.3 mm (the tip
  // starts 2.3 mm off, the task's fast pole is 17 /s) = 0.66 m/s^2: 0.03 mm. Hence 0.1 mm.
  const beside = await page.evaluate(() => {
    const api = window.opspaceLive, g = api.ghost;
    const f = g && api.trace.find((t) => t.t === g.t);
    return g && f ? { g, x: f.markers.x } : null;
  });
  const apart = beside && beside.g.visible ? Math.hypot(...beside.g.position.map((v, i) => v - beside.x[i])) : Infinity;
  check(apart < 1e-4, `unpushed, the ghost's ball is on the tip: ${(1000 * apart).toFixed(4)} mm apart at t = ${beside && beside.g.t.toFixed(3)} s (< 0.1 mm)`);
  const pressed = Date.now();
  const spot = await page.evaluate((body) => {
    const api = window.opspaceLive, o = api.screenOf(body);
    for (let r = 0; r <= 60; r += 4) {
      const around = Math.max(1, Math.round((2 * Math.PI * r) / 8));
      for (let k = 0; k < around; ++k) {
        const x = o.x + r * Math.cos((2 * Math.PI * k) / around), y = o.y + r * Math.sin((2 * Math.PI * k) / around);
        // A pixel well inside the body's picture: the arm moves on before the press.
        if ([[0, 0], [-5, 0], [5, 0], [0, -5], [0, 5]].every(([dx, dy]) => api.bodyAt(x + dx, y + dy) === body)) return { x, y, origin: o };
      }
    }
    return null;
  }, BODY);
  check(spot !== null, `body ${BODY} is drawn near its origin's pixel${spot ? ` (pressed at ${spot.x.toFixed(0)}, ${spot.y.toFixed(0)})` : ''}`);
  let pulled = null;
  if (spot) {
    await page.mouse.move(spot.x, spot.y);
    await page.mouse.down();
    const picked = await frameWhere((f) => f.push);
    check(picked !== null && picked.push.body === BODY, `pressing on body ${BODY} starts a push on it (${picked ? `body ${picked.push.body}` : 'no push'}, ${elapsed(pressed)} after the search began)`);
    await page.mouse.move(spot.x + 60, spot.y - 135, { steps: 10 });
    await sleep(1000);
    pulled = await frame();
    const force = pulled.push ? Math.hypot(...pulled.push.force) : 0;
    const label = page.locator('#push-label');
    const labelText = (await label.isVisible()) ? await label.textContent() : '(hidden)';
    check(force > 1 && /^\d+\.\d N$/.test(labelText), `the spring pulls with ${force.toFixed(1)} N, labelled '${labelText}'`);
    check(pulled.push && pulled.push.body === BODY && pulled.push.target.every(Number.isFinite), 'the frames show the pulled point and the mouse point');
    // The tip error plot's keys: the measured offset beside the one predicted for this push, both
    // above the millimetre PART3 holds unpushed (tests/live measures the prediction's accuracy).
    const shown = async () => Promise.all(['#value-0-0', '#value-0-1'].map(async (id) => Number(await page.locator(id).textContent())));
    const [measured, predicted] = await shown();
    check(measured > 1 && predicted > 1 && pulled.push !== null,
      `while pulled, the page shows the tip ${measured} mm off, and predicts ${predicted} mm for the push (|Jv A^-1 Je^T F| / kpx; > 1 mm each)`);
    await page.screenshot({ path: screenshot });
    console.log(`screenshot: ${screenshot}`);
    await page.mouse.up();
    const released = await frameWhere((f) => f.push === null && f.command >= window.opspaceLive.lastSent);
    // The page hides the label in its next animation frame, which may follow the frame seen here.
    const hidden = await label.waitFor({ state: 'hidden', timeout: 2000 }).then(() => true, () => false);
    check(released !== null && hidden, 'releasing the mouse ends the push and hides the label');
    const zero = await page.waitForFunction(() => Number(document.getElementById('value-0-1').textContent) === 0, null, { timeout: 5000 })
      .then(() => true, () => false);
    check(zero, 'released, the predicted offset goes back to 0 mm');
  }
  /// The frames of the run since the last reset, [t, poses] each.
  const thisRun = () => page.evaluate(() => {
    const api = window.opspaceLive, from = api.resetId;
    return api.trace.filter((f) => f.command >= from).map((f) => [f.t, f.poses]);
  });
  /// A run's poses at simulated time t, interpolated between the frames around it (positions
  /// only are used), or null when the run has no frames on both sides of t.
  const at = (run, t) => {
    for (let k = 0; k + 1 < run.length; ++k) {
      const [t0, p0] = run[k], [t1, p1] = run[k + 1];
      if (t0 <= t && t <= t1) {
        const w = t1 > t0 ? (t - t0) / (t1 - t0) : 0;
        return p0.map((v, i) => v + w * (p1[i] - v));
      }
    }
    return null;
  };

  // Reset again: the run starts over from the same pose, and goes as it went before the push
  // (the simulation is deterministic from a reset: the same steps, the same gains). The first
  // run's first frame, a little after t = 0, is compared with this run's at the same time.
  const first = await thisRun();
  const r2 = await resetRun();
  check(r2 && r2.t < 1, `reset again: the first frame after it is at t = ${r2 && r2.t.toFixed(3)} s (< 1 s)`);
  if (pulled) {
    // This run, unpushed, up to the time of the pull: body 2 is elsewhere then.
    const until = Math.max(pulled.t, r1 ? r1.t : 0) + 0.1;
    await frameWhere(new Function('f', `return f.t > ${until}`), 1000 * until + 20000);
  }
  const second = await thisRun();
  if (first.length && second.length) {
    // Both runs' poses at the later of their first frames' times, before the push began.
    const tc = Math.max(first[0][0], second[0][0]);
    const a = at(first, tc), b = at(second, tc);
    let worst = Infinity;
    if (a && b) {
      worst = 0;
      for (let i = 0; i < data.bodies; ++i) worst = Math.max(worst, moved(a, b, i));
    }
    check(tc < PUSH_FROM && worst < 0.005,
      `reset brings back the start pose: at t = ${tc.toFixed(3)} s every body origin is within ${(1000 * worst).toFixed(1)} mm of where it was after the first reset (< 5 mm)`);
  } else {
    check(false, 'reset brings back the start pose (no frames after a reset)');
  }
  if (pulled && second.length) {
    const unpushed = at(second, pulled.t);
    const shift = unpushed ? moved(pulled.poses, unpushed, BODY) : 0;
    check(shift > 0.02,
      `the push moves body ${BODY}: its origin is ${(1000 * shift).toFixed(0)} mm from where the same run unpushed has it at t = ${pulled.t.toFixed(2)} s (> 20 mm)`);
  }

  // Pause holds the pose; resume goes on.
  await page.locator('#pause').click();
  const paused = await frameWhere((f) => f.paused && f.command >= window.opspaceLive.lastSent);
  await sleep(600);
  const held = await frame();
  check(paused && held.paused && held.t === paused.t && held.poses.every((v, i) => v === paused.poses[i]),
    `pause holds t (${paused && paused.t.toFixed(3)} -> ${held.t.toFixed(3)} s) and every pose`);
  check((await page.locator('#pause').textContent()) === 'Resume', 'the pause button then says Resume');
  await page.locator('#pause').click();
  const resumed = await frameWhere(new Function('f', `return !f.paused && f.t > ${held.t} + 0.05`));
  check(resumed !== null, 'resume: simulated time goes on');

  // The law switch.
  if (data.laws.length > 1) {
    const from = (await frame()).law, to = from === 0 ? 1 : 0;
    await page.locator('#law').selectOption(String(to));
    const switched = await frameWhere(new Function('f', `return f.law === ${to}`));
    const s0 = await page.evaluate(() => ({ draws: window.opspaceLive.plotDraws, samples: window.opspaceLive.samples, t: window.opspaceLive.lastFrame.t }));
    await sleep(1000);
    const s1 = await page.evaluate(() => ({ draws: window.opspaceLive.plotDraws, samples: window.opspaceLive.samples, t: window.opspaceLive.lastFrame.t, error: window.opspaceLive.lastFrame.error }));
    check(switched !== null, `the law select switches the frames' law from ${from} to ${to} (${data.laws[to]})`);
    const ghostLaw = await page.waitForFunction((law) => window.opspaceLive.ghost && window.opspaceLive.ghost.law === law, to, { timeout: 5000 })
      .then(() => to, () => page.evaluate(() => window.opspaceLive.ghost && window.opspaceLive.ghost.law));
    check(ghostLaw === to, `the ghost draws the reference's path of the law in force (law ${ghostLaw})`);
    check(s1.t > s0.t && s1.samples > s0.samples && s1.draws > s0.draws,
      `after the switch the run goes on and the plots keep drawing (${s1.samples - s0.samples} samples, ${s1.draws - s0.draws} redraws in 1 s)`);
    check(s1.error === '', `no error under ${data.laws[to]}${s1.error ? `: ${s1.error}` : ''}`);
  } else {
    console.log('note: one control law: no law switch to check');
  }
  // The page's heading shows what the run shows, measured: the subtitle's first value is the tip
  // error of the plot's legend, and no promise. Seen to fail before (issue 46): "unpushed, PART3's
  // tip holds while joint 2 moves ...", no value.
  const heading = await page.evaluate(() => {
    const sub = document.getElementById('subtitle'), first = sub && sub.querySelector('.value');
    return { text: sub ? sub.textContent : '', value: first ? first.textContent : null, legend: document.getElementById('value-0-0').textContent };
  });
  check(!/\b(holds?|stays|keeps|wanders|comes back)\b/.test(heading.text) && heading.value !== null && heading.value === heading.legend &&
    Number.isFinite(Number(heading.value)) && /\|x - x_d\| = [-0-9.e+]+ mm/.test(heading.text),
  `the subtitle shows the measured tip error, no promise: '${heading.text}' (legend: ${heading.legend} mm)`);

  // No plot label is clipped: every label's box (measured as drawn) lies inside its canvas, with
  // the run's values and with values whose labels are the widest the plots write (10 characters).
  // Seen to fail with the plots' fixed 48 px margin: '-0.0001234' from x = -15.2 (joint 2 of a
  // PART3 run drew '-0.000001938').
  const clipped = (drawn) => drawn.flatMap((p, i) => p.boxes.filter((b) => b.left < 0 || b.top < 0 || b.right > p.width || b.bottom > p.height)
    .map((b) => `drawing ${i}: '${b.text}' at x ${b.left.toFixed(1)}..${b.right.toFixed(1)}, y ${b.top.toFixed(1)}..${b.bottom.toFixed(1)} of ${p.width} x ${p.height}`));
  const asRun = await page.evaluate(() => { window.opspaceLive.plots.draw(window.opspaceLive.lastFrame.t); return window.opspaceLive.plotLabels; });
  const wide = await page.evaluate(() => {
    const api = window.opspaceLive, n = api.data.plots.reduce((k, p) => k + p.series.length, 0), drawn = [];
    for (const [a, b] of [[-0.00012345, -0.00023456], [-1.2345e-7, -9.876e-8], [1.2345e21, -12345.6], [-1.9384e-6, -0.5384]]) {
      api.plots.clear();
      api.plots.add([[0, ...Array(n).fill(a)], [1, ...Array(n).fill(b)]]);
      api.plots.draw(1);
      drawn.push(...api.plotLabels);
    }
    api.plots.clear();
    return drawn;
  });
  const outside = [...clipped(asRun), ...clipped(wide)];
  check(asRun.length === data.plots.length && outside.length === 0,
    `every plot label lies inside its canvas (${asRun.length} plots as run, ${wide.length} with wide labels)${outside.length ? `: ${outside.join('; ')}` : ''}`);

  const latencies = await page.evaluate(() => window.opspaceLive.latencies);
  const sorted = [...latencies].sort((x, y) => x - y);
  check(latencies.length > 0, `every command is acknowledged by a frame: ${latencies.length} latencies, median ${sorted.length ? sorted[sorted.length >> 1].toFixed(0) : '-'} ms, ` +
    `max ${sorted.length ? sorted[sorted.length - 1].toFixed(0) : '-'} ms`);
  check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);

  // A command the server refuses (400) is shown on the page (Chromium logs the 400: not an error here).
  await page.evaluate(() => window.opspaceLive.send({ command: 'no-such-command' }));
  const refused = await page.waitForFunction(() => /refused/.test(document.getElementById('status').textContent), null, { timeout: 5000 })
    .then(() => page.locator('#status').textContent(), () => null);
  check(refused !== null, `a refused command is shown: '${refused}'`);

  // SIGINT: the program ends cleanly, its port closed, and the page says so.
  const sent = Date.now();
  child.kill('SIGINT');
  const ended = await Promise.race([exit, sleep(3000).then(() => null)]);
  let late = '';
  if (!ended) {  // how late, for the report
    const eventually = await Promise.race([exit, sleep(20000).then(() => null)]);
    late = eventually ? `: it exited with ${eventually.code ?? eventually.signal} after ${Date.now() - sent} ms` : ': still running after 23 s';
  }
  check(ended !== null && ended.code === 0, `SIGINT: the program exits with status 0 within 3 s (${ended ? `${ended.code ?? ended.signal} after ${Date.now() - sent} ms` : `too late${late}`})`);
  check(await portClosed(live.port), `nothing listens on port ${live.port} any more`);
  const told = await page.waitForFunction(() => window.opspaceLive.stopped && document.getElementById('stopped').offsetParent !== null, null, { timeout: 5000 })
    .then(() => true, () => false);
  check(told, 'the page says that the program has stopped');
} catch (e) {
  check(false, `the check ran to its end (${e.message.split('\n')[0]})`);
} finally {
  if (browser) await browser.close();
  if (!exited) {
    child.kill('SIGKILL');
    await exit;
  }
  if (failures.length) printOutput();
  cleanUp();
}
if (failures.length) {
  console.log(`${failures.length} check(s) failed`);
  process.exit(1);
}
