// Loads the grader's report page (hw2-grade --html, out/grade/report.html) in Debian's headless
// Chromium (driven by playwright-core), offline, and checks what a student reads there:
//   node check_report_page.mjs PAGE.html SCREENSHOT.png [TEST]
// Exit 0: the page loaded from its file alone (every other request refused and counted as an
// error), no console error, every failed simulated test has a figure whose plot draws the
// student's run, and, for TEST (its "<key> <name>"), the reference's run and the bound too (a
// simulated TEST) or a table of entries with the wrong ones shaded red (a formula TEST); the
// screenshot is of TEST's section (or of the page's top). 1: a check failed; 77: no Chromium.
import { pathToFileURL } from 'node:url';
import { checkInPage, offline } from './chromium.mjs';

const [page_file, screenshot, focus] = process.argv.slice(2);
if (!page_file || !screenshot) {
  console.error('usage: node check_report_page.mjs PAGE.html SCREENSHOT.png [TEST]');
  process.exit(2);
}

await checkInPage({ width: 1000, height: 900 }, async ({ page, errors, check }) => {
  const url = pathToFileURL(page_file).href;
  await offline(page, url);
  await page.goto(url);
  const tests = await page.$$eval('section.test', (sections) => sections.map((s) => ({
    name: s.dataset.test,
    failed: s.dataset.status !== 'PASS',
    simulated: s.dataset.simulated === '1',
    wrong: [...s.querySelectorAll('table.entries .wrong')].map((r) => getComputedStyle(r).backgroundColor),
    figures: [...s.querySelectorAll('figure.run')].map((f) => ({
      student: f.querySelectorAll('svg polyline.student').length,
      reference: f.querySelectorAll('svg polyline.reference').length,
      bound: f.querySelectorAll('svg line.bound').length,
      width: f.querySelector('svg') ? f.querySelector('svg').getBoundingClientRect().width : 0,
    })),
  })));
  check(tests.length > 0, `the page shows ${tests.length} tests`);
  const failed = tests.filter((t) => t.failed && t.simulated);
  // A page of formula tests alone (problem 1a's) has no simulated test to fail.
  const focused = focus ? tests.find((x) => x.name === focus) : undefined;
  if (!focused || focused.simulated) check(failed.length > 0, `${failed.length} failed simulated tests`);
  for (const t of failed) {
    check(t.figures.length > 0 && t.figures.every((f) => f.student === 1 && f.width > 100),
      `"${t.name}" has its figure (${t.figures.length}), each plotting the student's run`);
  }
  if (focus) {
    const t = tests.find((x) => x.name === focus);
    check(t !== undefined, `the page has "${focus}"`);
    if (t && t.simulated) {
      check(t.figures.some((f) => f.reference === 1 && f.bound === 1),
        `"${focus}" plots the reference's run and the bound beside the student's`);
    } else if (t) {
      // A formula test: its table marks the wrong entries, shaded red by the page's style (a
      // background whose red channel is above both others).
      const red = (c) => { const [r, g, b] = (c.match(/\d+/g) || []).map(Number); return r > g && r > b; };
      check(t.failed && t.wrong.length > 0 && t.wrong.every(red),
        `"${focus}" failed and its table marks ${t.wrong.length} entries wrong, shaded red (${t.wrong.join(', ')})`);
    }
  }
  check(errors.length === 0, `no console error or refused request${errors.length ? `: ${errors.join('; ')}` : ''}`);
  const target = focus ? page.locator(`section.test[data-test="${focus.replace(/"/g, '\\"')}"]`) : page.locator('body');
  await target.screenshot({ path: screenshot });
});
