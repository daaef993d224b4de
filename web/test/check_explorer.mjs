// Loads the explorer page in Debian's headless Chromium (driven by playwright-core) and checks
// that its numbers are the native library's and that its drawings follow the sliders:
//   node check_explorer.mjs PAGE.html OPSPACE_EXPLORER ARTEFACT_DIR
// OPSPACE_EXPLORER is the native program (web/explorer/main.cpp): `view` prints, for the same
// request, what the page's WebAssembly module computes. Exit 0: every check passed; 1: one
// failed; 77: no Chromium (ctest SKIP). Screenshots of each robot go to ARTEFACT_DIR.
import { execFileSync } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { checkInPage, definePixelTools } from './chromium.mjs';

const [page_file, native, artefacts] = process.argv.slice(2);
if (!page_file || !native || !artefacts) {
  console.error('usage: node check_explorer.mjs PAGE.html OPSPACE_EXPLORER ARTEFACT_DIR');
  process.exit(2);
}
mkdirSync(artefacts, { recursive: true });

/// The largest difference between two view results, |a - b| / max(1, |a|), walking both.
/// Directions (the columns of 'axes', each 'u') are defined up to sign: each is compared with
/// the other's column or its negative, whichever is nearer.
function difference(a, b, path = '', key = '') {
  if (a === null || b === null) return { d: a === b ? 0 : Infinity, where: path };
  if (typeof a === 'number') return { d: Math.abs(a - b) / Math.max(1, Math.abs(a)), where: path };
  if (Array.isArray(a)) {
    if (!Array.isArray(b) || a.length !== b.length) return { d: Infinity, where: `${path} (length)` };
    const direction = key === 'u' || key === 'axes-column';
    let worst = { d: 0, where: path };
    const compare = (bb) => {
      let w = { d: 0, where: path };
      a.forEach((x, i) => {
        const r = difference(x, bb[i], `${path}[${i}]`, key === 'axes' ? 'axes-column' : '');
        if (r.d > w.d) w = r;
      });
      return w;
    };
    worst = compare(b);
    if (direction) {
      const flipped = compare(b.map((x) => -x));
      if (flipped.d < worst.d) worst = flipped;
    }
    return worst;
  }
  let worst = { d: 0, where: path };
  for (const k of Object.keys(a)) {
    if (!(k in b)) return { d: Infinity, where: `${path}.${k} (missing)` };
    const r = difference(a[k], b[k], `${path}.${k}`, k);
    if (r.d > worst.d) worst = r;
  }
  return worst;
}

await checkInPage({ width: 1400, height: 900 }, async ({ page, errors, check }) => {
  await definePixelTools(page);
  await page.goto(pathToFileURL(page_file).href);
  await page.waitForFunction(() => window.opspaceExplorer && window.opspaceExplorer.ready, null, { timeout: 60000 });
  const robots = await page.evaluate(() => window.opspaceExplorer.robots);
  check(robots.join(' ') === 'pp puma iiwa rrr', `the page offers the four robots (${robots.join(', ')})`);

  // 1. The page's numbers are the native library's: at each robot's opening configuration and
  // at two others (every joint moved by +-0.3 of its range's half-width from the middle of the
  // range, alternating), with the tip and self-motion sliders moved. 1e-12: both run the same
  // C++ on IEEE doubles; only the maths library (sin, cos) may differ, by an ulp.
  const data = await page.evaluate(() => JSON.parse(document.getElementById('opspace-explorer-data').textContent));
  let worst = { d: 0, where: '' }, compared = 0;
  for (const r of data.robots) {
    const middle = r.joints.map((j) => (j.lower + j.upper) / 2);
    const half = r.joints.map((j) => (j.upper - j.lower) / 2);
    const configurations = [
      { q: r.q0, u: [1, 0, 0], tipS: 0, selfJoint: r.self_joint, selfS: 0 },
      { q: middle.map((m, i) => m + (i % 2 ? -0.3 : 0.3) * half[i]), u: [1, 0, 0], tipS: 0.05, selfJoint: r.self_joint, selfS: 0.3 },
      { q: middle.map((m, i) => m + (i % 2 ? 0.3 : -0.3) * half[i]), u: [0, 0.6, 0.8], tipS: -0.04, selfJoint: 0, selfS: -0.2 },
    ];
    for (const req of configurations) {
      const inPage = await page.evaluate(([key, rq]) => window.opspaceExplorer.compute(key, rq), [r.key, req]);
      const out = execFileSync(native, ['view', r.key, req.q.join(','), req.u.join(','), String(req.tipS),
        String(req.selfJoint), String(req.selfS)], { encoding: 'utf8' });
      const d = difference(JSON.parse(out), inPage, r.key);
      if (d.d > worst.d) worst = d;
      ++compared;
    }
  }
  check(worst.d <= 1e-12, `at ${compared} requests the page's numbers equal the native library's ` +
    `(largest relative difference ${worst.d.toExponential(2)}${worst.d ? ' at ' + worst.where : ''}, at most 1e-12)`);

  // 2. The 3R arm at problem 4's configuration theta = (0, 90 deg, 0): two singular directions,
  // Z0 of Type I and Y0 of Type II (problem 4 ii-iv), drawn as arrows of their type's colour.
  await page.evaluate(() => { window.opspaceExplorer.select('rrr'); window.opspaceExplorer.setQ([0, Math.PI / 2, 0]); });
  const rrr = await page.evaluate(() => ({ view: window.opspaceExplorer.view(), arrows: window.opspaceExplorer.arrows() }));
  const along = (u, axis) => Math.abs(u[axis]) > 1 - 1e-9;
  check(rrr.view.singular.length === 2, `the 3R arm at (0, 90 deg, 0) has ${rrr.view.singular.length} singular directions (2)`);
  check(rrr.view.singular.some((s) => s.type === 1 && along(s.u, 2)), 'Z0 is a singular direction of Type I');
  check(rrr.view.singular.some((s) => s.type === 2 && along(s.u, 1)), 'Y0 is a singular direction of Type II');
  check(rrr.arrows.length === 2 && rrr.arrows.some((a) => a.type === 1 && along(a.u, 2) && a.color === '#e67e22') &&
    rrr.arrows.some((a) => a.type === 2 && along(a.u, 1) && a.color === '#8e44ad'),
  'two arrows are drawn: Z0 in Type I orange, Y0 in Type II purple');
  await page.screenshot({ path: `${artefacts}/explorer-rrr.png` });

  // 3. The PP robot, problem 1a-vi: a tip motion of 0.1 m along X0 moves d1 and d2 by 0.05 m
  // each through J+ = [1/2 1/2]^T, and only d2 (the light link) by 0.1 m through Jbar = [0 1]^T.
  await page.evaluate(() => window.opspaceExplorer.select('pp'));
  await page.locator('#tip-direction').selectOption('X0');
  await page.locator('#tip-s').fill('0.1');
  const pp = await page.evaluate(() => window.opspaceExplorer.view());
  const near = (q, expected) => q.every((x, i) => Math.abs(x - expected[i]) < 1e-9);
  check(near(pp.pseudo_inverse.q, [0.05, 0.05]), `J+ moves the PP robot by (${pp.pseudo_inverse.q}) (0.05, 0.05)`);
  check(near(pp.dynamically_consistent.q, [0, 0.1]), `Jbar moves the PP robot by (${pp.dynamically_consistent.q}) (0, 0.1): the light link only`);
  await page.screenshot({ path: `${artefacts}/explorer-pp.png` });

  // 4. Moving a slider changes the drawn ellipsoids: with the robot hidden, the main view shows
  // the ellipsoids (and arrows, none on the iiwa here; the lower views show the arm); turning joint 2 by 0.5 rad moves the
  // tip by tens of centimetres and turns the ellipsoids, so many of their pixels change.
  await page.evaluate(() => window.opspaceExplorer.select('iiwa'));
  const pixels = await page.evaluate(() => {
    const api = window.opspaceExplorer;
    const canvas = document.getElementById('canvas');
    const grab = () => window.opspaceTest.pixels(canvas);
    api.setRobotVisible(false);
    const before = grab();
    const q1 = parseFloat(document.getElementById('q1').value);
    api.setJoint(1, q1 + 0.5);
    api.setRobotVisible(false);
    const after = grab();
    api.setRobotVisible(true);
    let changed = 0;
    for (let i = 0; i < before.length / 4; ++i) if (window.opspaceTest.differs(before, after, i)) ++changed;
    return { changed: changed / (before.length / 4) };
  });
  check(pixels.changed > 0.005, `moving joint 2 of the iiwa changes ${(100 * pixels.changed).toFixed(2)} % of the canvas's pixels with the robot hidden in the top view (> 0.5 %)`);

  // 5. Redraw time of a slider move on the iiwa (compute and render the three views, waiting for
  // the GPU process to finish drawing them), measured in the page: reported for
  // docs/performance.md, not judged here (a benchmark, not a test).
  const timing = await page.evaluate(() => {
    const api = window.opspaceExplorer;
    api.waitForGpu = true;
    api.redrawMs.length = 0;
    api.computeMs.length = 0;
    const q0 = parseFloat(document.getElementById('q3').value);
    for (let k = 0; k < 60; ++k) api.setJoint(3, q0 + 0.01 * (k % 20));
    api.waitForGpu = false;
    const t = api.redrawMs.slice().sort((a, b) => a - b);
    const c = api.computeMs.slice().sort((a, b) => a - b);
    return { median: t[Math.floor(t.length / 2)], p90: t[Math.floor(0.9 * t.length)], max: t[t.length - 1], n: t.length,
      compute: c[Math.floor(c.length / 2)], pixels: document.querySelectorAll('canvas').length &&
        [...document.querySelectorAll('canvas')].map((x) => `${x.width}x${x.height}`).join(' + ') };
  });
  console.log(`redraw after a slider move on the iiwa: median ${timing.median.toFixed(2)} ms, 90th percentile ` +
    `${timing.p90.toFixed(2)} ms, max ${timing.max.toFixed(2)} ms over ${timing.n} moves; of which the ` +
    `library's computation (WebAssembly) median ${timing.compute.toFixed(2)} ms; canvases ${timing.pixels}`);
  await page.screenshot({ path: `${artefacts}/explorer-iiwa.png` });
  await page.evaluate(() => window.opspaceExplorer.select('puma'));
  await page.locator('#self-s').fill('0.6');
  await page.screenshot({ path: `${artefacts}/explorer-puma.png` });
  check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
});
