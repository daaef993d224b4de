// The live lab's benchmark (issue 32's goals; the results are in docs/performance.md, "The live
// lab"). For each problem's solution program it starts `PROGRAM ARG... --live --port 0`, opens
// the page in headless Chromium (1280x720) and, for SECONDS (15), sends a command about every
// 200 ms as a person would: a gain moved back and forth, and a drag (a push on a link whose
// mouse point circles for 0.6 s, then a release; every 2 s). Then it prints, per program:
//   rtf       the real-time factor in the frames (frame.rtf: simulated over wall seconds in the
//             program's last half second): median, and min after the window's first second
//   latency   from a POST /command to the first frame that applied it, measured by the page
//             (window.opspaceLive.latencies): median and 95th percentile, ms
//   fps       frames the page received per wall second
//   main      CPU of the program's main thread, % of one core: the simulation, the pacing and
//             the encoding of the frames (JSON) all happen on it
//   server    CPU of all its other threads (cpp-httplib's: listening, streaming the frames,
//             answering the commands), % of one core
// from /proc/PID/task/*/stat (utime + stime) at the window's start and end, over its wall time;
//   draws     the page's animation frames per second (requestAnimationFrame): below 60 the
//             page's main thread, which also receives the frames, is busy drawing
//   without the browser: the latency of the same gain commands sent by this script for 5 s
//             after the window, following /events itself (the page still open): the program's
//             share of the latency.
// The 1-minute load average (/proc/loadavg) at the start and the end of each window is printed
// too: the machine's other work competes with the program and with Chromium.
// Run it from the build tree (it needs playwright-core, which the build's `npm ci` installs):
//   nice -n 10 node build/release/web/test/bench_live.mjs build/release/apps [SECONDS] [--json OUT]
// (or from web/test with web/node_modules present). OPSPACE_LIVE_VIEWER selects the page's
// bundle, as for the programs. Exit 0 when every program ran, 1 otherwise, 77 when Chromium or
// playwright-core is missing.
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const args = process.argv.slice(2);
const jsonAt = args.indexOf('--json');
const jsonOut = jsonAt >= 0 ? args.splice(jsonAt, 2)[1] : null;
const [apps, secondsArg] = args;
if (!apps) {
  console.error('usage: node bench_live.mjs APPS_DIR [SECONDS] [--json OUT]');
  process.exit(2);
}
const SECONDS = Number(secondsArg || 15);
const PERIOD = 200;  // ms between commands
// Up to a frame period (1/60 s) added at random to each send time: with exactly 200 ms, 12 frame
// periods, every command would come at the same point of the frame cycle, and the latencies
// would all be alike, by chance short or long.
const jitter = () => Math.random() * 1000 / 60;
const PROGRAMS = [
  ['hw2-p1-sol', ['3']], ['hw2-p2-sol', []], ['hw2-p3-sol', []], ['hw2-p4-sol', ['z']],
];
if (!existsSync(process.env.CHROMIUM || '/usr/bin/chromium')) {
  console.log('SKIP: Chromium is not installed (apt-get install chromium)');
  process.exit(77);
}
let helpers;
try {
  helpers = await import('./chromium.mjs');
} catch (e) {
  console.log(`SKIP: playwright-core is not installed here (run this from the build tree): ${e.message}`);
  process.exit(77);
}
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const load = () => Number(readFileSync('/proc/loadavg', 'utf8').split(' ')[0]);
const TICK = 100;  // clock ticks a second (getconf CLK_TCK on Linux)

/// Each thread's CPU seconds (utime + stime) and name: { tid: { cpu, name } }.
function threads(pid) {
  const out = {};
  for (const tid of readdirSync(`/proc/${pid}/task`)) {
    try {
      const stat = readFileSync(`/proc/${pid}/task/${tid}/stat`, 'utf8');
      const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');  // fields from the 3rd
      const name = readFileSync(`/proc/${pid}/task/${tid}/comm`, 'utf8').trim();
      out[tid] = { cpu: (Number(fields[11]) + Number(fields[12])) / TICK, name };
    } catch { /* the thread ended meanwhile */ }
  }
  return out;
}
const quantile = (values, q) => {
  if (!values.length) return NaN;
  const s = [...values].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.floor(q * s.length))];
};
const median = (values) => quantile(values, 0.5);

/// Sends a gain command every PERIOD ms for `seconds` from this process (ids from 10^9, above
/// the page's) and follows /events itself: the latencies from each POST to the first frame that
/// applied it, without the browser.
async function probeServer(url, gain, seconds) {
  const controller = new AbortController();
  const response = await fetch(`${url}events`, { signal: controller.signal });
  const reader = response.body.getReader();
  const decoder = new TextDecoder();
  const waiting = new Map();  // id -> when sent
  const latencies = [];
  let buffer = '';
  const reading = (async () => {
    for (;;) {
      const { value, done } = await reader.read().catch(() => ({ done: true }));
      if (done) return;
      const now = performance.now();
      buffer += decoder.decode(value, { stream: true });
      let cut;
      while ((cut = buffer.indexOf('\n\n')) >= 0) {
        const message = buffer.slice(0, cut);
        buffer = buffer.slice(cut + 2);
        if (!message.startsWith('data: ')) continue;
        const m = message.match(/"command":(\d+)/);
        if (!m) continue;
        for (const [id, at] of waiting) if (id <= Number(m[1])) { latencies.push(now - at); waiting.delete(id); }
      }
    }
  })();
  const t0 = Date.now();
  for (let k = 0; Date.now() - t0 < seconds * 1000; ++k) {
    const id = 1e9 + k;
    const value = k % 2 ? gain.value : Math.min(gain.max, gain.value + 0.2 * (gain.max - gain.min));
    waiting.set(id, performance.now());
    await fetch(`${url}command`, { method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ id, command: 'gain', name: gain.name, value }) });
    await sleep(t0 + (k + 1) * PERIOD + jitter() - Date.now());
  }
  await sleep(200);
  controller.abort();
  await reading;
  return latencies;
}

async function bench(browser, [name, programArgs]) {
  const program = path.join(apps, name);
  const work = mkdtempSync(path.join(os.tmpdir(), 'opspace-bench-live-'));
  const argv = [...programArgs, '--no-plots', '--no-replay', '--live', '--port', '0'];
  const child = spawn(program, argv, { cwd: work, env: { ...process.env, OPSPACE_OUT: path.join(work, 'out') }, stdio: ['ignore', 'pipe', 'pipe'] });
  let output = '', exited = null;
  const exit = new Promise((resolve) => child.on('exit', (code, signal) => { exited = { code, signal }; resolve(exited); }));
  child.stdout.on('data', (d) => { output += d; });
  child.stderr.on('data', (d) => { output += d; });
  const result = { program: `${name} ${programArgs.join(' ')}`.trim() };
  let page = null;
  try {
    const deadline = Date.now() + 60000;
    let url = null;
    while (!url && !exited && Date.now() < deadline) {
      const m = output.match(/^live: (http:\/\/127\.0\.0\.1:\d+\/)\s*$/m);
      if (m) url = m[1]; else await sleep(50);
    }
    if (!url) throw new Error(`no live URL (${exited ? `exited with ${exited.code ?? exited.signal}` : 'none in 60 s'})`);
    ({ page } = await helpers.openPage(browser, { width: 1280, height: 720 }));
    await page.goto(url);
    await page.waitForFunction(() => window.opspaceLive && window.opspaceLive.ready, null, { timeout: 30000 });
    const data = await page.evaluate(() => window.opspaceLive.data);
    const gain = data.gains[0] || null;
    const body = Math.min(2, data.bodies - 1);  // the PUMA's forearm; the iiwa's third link

    // The window: the page records each frame's arrival, rtf and command.
    await page.evaluate(() => {
      const api = window.opspaceLive, record = [];
      api.benchRecord = record;
      api.benchLatencies = api.latencies.length;
      api.trace = { push: (f) => record.push([performance.now(), f.rtf, f.t, f.error]) };
      const draws = [];  // the page's animation frames: how busy its main thread is
      api.benchDraws = draws;
      const loop = (t) => { draws.push(t); if (!api.benchStop) requestAnimationFrame(loop); };
      requestAnimationFrame(loop);
    });
    const start = threads(child.pid);
    const loadStart = load();
    const t0 = Date.now();
    let origin = null, sent = 0;
    for (let k = 0; Date.now() - t0 < SECONDS * 1000; ++k) {
      const phase = k % 10;
      let command = null;
      if (phase % 2 === 0 || phase === 9) {
        if (gain) {
          const high = Math.min(gain.max, gain.value + 0.2 * (gain.max - gain.min));
          command = { command: 'gain', name: gain.name, value: k % 4 === 0 ? gain.value : high };
        } else {
          command = { command: 'speed', value: 1 };
        }
      } else if (phase <= 5) {  // the drag: the mouse point circles 5 cm around where it began
        if (phase === 1) {
          const p = (await page.evaluate(() => window.opspaceLive.lastFrame)).poses;
          origin = [p[7 * body], p[7 * body + 1], p[7 * body + 2]];
        }
        const a = (Math.PI / 2) * (phase - 1);
        const target = [origin[0] + 0.05 * Math.cos(a), origin[1] + 0.05 * Math.sin(a), origin[2] + 0.05];
        command = { command: 'push', body, point: [0, 0, 0], target };
      } else {
        command = { command: 'release' };
      }
      await page.evaluate((c) => window.opspaceLive.send(c), command);
      ++sent;
      await sleep(t0 + (k + 1) * PERIOD + jitter() - Date.now());
    }
    await page.evaluate(() => window.opspaceLive.send({ command: 'release' }));
    const wall = (Date.now() - t0) / 1000;
    const end = threads(child.pid);
    const loadEnd = load();
    const page_ = await page.evaluate(() => {
      const api = window.opspaceLive;
      api.benchStop = true;
      return { record: api.benchRecord, latencies: api.latencies.slice(api.benchLatencies), errors: api.commandErrors, draws: api.benchDraws };
    });
    // The program's share of the latency: the same commands from this process, the page still open.
    const probe = gain ? await probeServer(url, gain, 5) : [];
    const record = page_.record;
    const from = record.length ? record[0][0] : 0;
    const rtfs = record.map((r) => r[1]);
    const settled = record.filter((r) => r[0] >= from + 1000).map((r) => r[1]);
    let main = 0, others = 0;
    const perThread = [];
    for (const [tid, t] of Object.entries(end)) {
      const used = t.cpu - (start[tid] ? start[tid].cpu : 0);
      perThread.push({ tid: Number(tid), name: t.name, main: Number(tid) === child.pid, percent: (100 * used) / wall });
      if (Number(tid) === child.pid) main += used; else others += used;
    }
    Object.assign(result, {
      seconds: wall, loadStart, loadEnd, commands: sent, acknowledged: page_.latencies.length,
      rtfMedian: median(rtfs), rtfMin: settled.length ? Math.min(...settled) : NaN,
      latencyMedian: median(page_.latencies), latencyP95: quantile(page_.latencies, 0.95),
      latencyMax: page_.latencies.length ? Math.max(...page_.latencies) : NaN,
      fps: record.length / wall, draws: page_.draws.length / wall,
      drawGapP95: quantile(page_.draws.slice(1).map((t, i) => t - page_.draws[i]), 0.95),
      probeMedian: median(probe), probeP95: quantile(probe, 0.95), mainPercent: (100 * main) / wall, serverPercent: (100 * others) / wall,
      threads: perThread.sort((a, b) => b.percent - a.percent).slice(0, 6),
      refused: page_.errors.length, refusedFirst: page_.errors[0] || '',
      runError: record.map((r) => r[3]).find((e) => e) || '',
    });
  } catch (e) {
    result.failed = e.message.split('\n')[0];
  } finally {
    if (page) await page.close();
    if (!exited) child.kill('SIGINT');
    if (!(await Promise.race([exit, sleep(10000).then(() => null)]))) {
      child.kill('SIGKILL');
      await exit;
    }
    rmSync(work, { recursive: true, force: true });
  }
  if (result.failed) console.log(`--- ${name} said:\n${output.trimEnd()}\n---`);
  return result;
}

const browser = await helpers.launch();
const results = [];
try {
  for (const p of PROGRAMS) {
    const r = await bench(browser, p);
    results.push(r);
    if (r.failed) {
      console.log(`${r.program}: FAILED: ${r.failed}`);
    } else {
      console.log(`${r.program}: ${r.seconds.toFixed(1)} s, load ${r.loadStart.toFixed(2)} -> ${r.loadEnd.toFixed(2)}, ` +
        `${r.commands} commands, ${r.acknowledged} acknowledged, ${r.refused} refused${r.refused ? ` (${r.refusedFirst})` : ''}` +
        `${r.runError ? `, run error: ${r.runError}` : ''}; busiest threads: ` +
        r.threads.map((t) => `${t.main ? 'main' : t.tid} ${t.name} ${t.percent.toFixed(1)} %`).join(', '));
    }
    await sleep(2000);  // the program's exit settles before the next one starts
  }
} finally {
  await browser.close();
}

const f = (v, d = 1) => (Number.isFinite(v) ? v.toFixed(d) : '-');
console.log('\n| program | load (1 min) | rtf median | rtf min | latency median | latency p95 | fps | main thread | server threads | page draws/s | without the browser: median, p95 |');
console.log('|---|---|---|---|---|---|---|---|---|---|---|');
for (const r of results) {
  if (r.failed) { console.log(`| ${r.program} | failed: ${r.failed} |`); continue; }
  console.log(`| ${r.program} | ${f(r.loadStart, 2)} -> ${f(r.loadEnd, 2)} | ${f(r.rtfMedian, 2)} | ${f(r.rtfMin, 2)} | ` +
    `${f(r.latencyMedian)} ms | ${f(r.latencyP95)} ms | ${f(r.fps)} | ${f(r.mainPercent)} % | ${f(r.serverPercent)} % | ` +
    `${f(r.draws)} | ${f(r.probeMedian)} ms, ${f(r.probeP95)} ms |`);
}
if (jsonOut) writeFileSync(jsonOut, JSON.stringify(results, null, 1));
process.exit(results.some((r) => r.failed) ? 1 : 0);
