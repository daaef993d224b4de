// Loads the class page (scripts/regrade's OUT/class.html, hw2-class) in Debian's headless
// Chromium (driven by playwright-core), offline, and checks what an instructor reads there:
//   node check_class_page.mjs PAGE.html SCREENSHOT.png
// Exit 0: the page loaded from its file alone (every other request refused and counted as an
// error), no console error, no script ran (a student's name with a <script> in it stays text),
// every simulated test of the class (a test named "... in simulation ...", the suite's wording)
// has a figure of small multiples whose every plot draws at least one student's run, the
// reference's run and the bound (where the run has one), and the mistakes table has a row per
// mistake of the page's data; it opened within 2 s (the issue's goal; the time is printed). The
// screenshot is of the mistakes table and the first three judged runs' plots. 1: a check
// failed; 77: no Chromium.
import { pathToFileURL } from 'node:url';
import { checkInPage, offline } from './chromium.mjs';

const [page_file, screenshot] = process.argv.slice(2);
if (!page_file || !screenshot) {
  console.error('usage: node check_class_page.mjs PAGE.html SCREENSHOT.png');
  process.exit(2);
}

await checkInPage({ width: 1400, height: 1000 }, async ({ page, errors, check }) => {
  const url = pathToFileURL(page_file).href;
  await offline(page, url);
  // A script of the page's own would set this; a student's injected one would too.
  await page.addInitScript(() => { window.__alerts = 0; window.alert = () => { window.__alerts += 1; }; });
  const start = Date.now();
  await page.goto(url, { waitUntil: 'load' });
  const seconds = (Date.now() - start) / 1000;
  console.log(`opened in ${seconds.toFixed(2)} s`);
  // 2 s: the issue's goal for a class of 200 on this machine.
  check(seconds < 2, `the page opens within 2 s (${seconds.toFixed(2)} s)`);
  const data = JSON.parse(await page.$eval('#class-data', (e) => e.textContent));
  const runs = await page.$$eval('figure.class-run', (figures) => figures.map((f) => ({
    test: f.dataset.test,
    statistic: f.dataset.statistic,
    bounded: f.dataset.bound === '1',
    panels: [...f.querySelectorAll('.panel')].map((p) => ({
      runs: p.querySelectorAll('svg path.run').length,
      reference: p.querySelectorAll('svg polyline.reference').length,
      bound: p.querySelectorAll('svg line.bound').length,
      width: p.querySelector('svg') ? p.querySelector('svg').getBoundingClientRect().width : 0,
    })),
  })));
  const simulated = data.problems.flatMap((p) => p.tests.map((t) => t.test)).filter((t) => t.includes(' in simulation '));
  check(simulated.length > 0 && runs.length === data.runs.length, `${runs.length} judged runs drawn, as many as the data's`);
  for (const test of simulated) check(runs.some((r) => r.test === test), `"${test}" has its figure`);
  for (const r of runs) {
    check(r.panels.length > 0 && r.panels.every((p) => p.runs > 0 && p.reference === 1 && p.bound === (r.bounded ? 1 : 0) && p.width > 100),
      `"${r.test}" (${r.statistic}): ${r.panels.length} plots, each with students' runs, the reference's${r.bounded ? ' and the bound' : ''}`);
  }
  const rows = await page.$$eval('tr.mistake', (trs) => trs.length);
  check(rows === data.mistakes.length && rows > 0, `${rows} rows of known mistakes, as in the data (${data.mistakes.length})`);
  check(await page.evaluate(() => window.__alerts) === 0, 'no script ran');
  check(errors.length === 0, `no console error or refused request${errors.length ? `: ${errors.join('; ')}` : ''}`);
  // The mistakes ranked, then the first simulated tests' plots: what an instructor reads first.
  const top = await page.$eval('#mistakes', (e) => e.getBoundingClientRect().top + window.scrollY);
  const bottom = await page.$$eval('figure.class-run', (fs) => {
    const f = fs[Math.min(2, fs.length - 1)];
    return f ? f.getBoundingClientRect().bottom + window.scrollY : 1000;
  });
  await page.screenshot({ path: screenshot, fullPage: true, clip: { x: 0, y: top, width: 1400, height: Math.max(200, bottom - top) } });
});
