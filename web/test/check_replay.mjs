// Loads a replay page in Debian's headless Chromium (driven by playwright-core) and checks
// that a person would see the robot move:
//   node check_replay.mjs PAGE.html SCREENSHOT.png
// Exit 0: the page loaded without console errors, play/pause and the slider work, the robot
// covers part of the view and moves; 1: a check failed; 77: no Chromium (ctest SKIP).
import { existsSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

const [page_file, screenshot] = process.argv.slice(2);
if (!page_file || !screenshot) {
  console.error('usage: node check_replay.mjs PAGE.html SCREENSHOT.png');
  process.exit(2);
}
const executable = process.env.CHROMIUM || '/usr/bin/chromium';
if (!existsSync(executable)) {
  console.log(`SKIP: no Chromium at ${executable} (apt-get install chromium; bash scripts/test installs it)`);
  process.exit(77);
}

const failures = [];
const check = (ok, what) => {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures.push(what);
};

// The flags Chromium needs on a machine with no GPU and a closed network. WebGL then runs on
// SwiftShader, which Chromium only allows for trusted content when asked to.
const browser = await chromium.launch({
  executablePath: executable,
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--enable-unsafe-swiftshader'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1200, height: 800 } });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()}`));

  await page.goto(`${pathToFileURL(page_file).href}#t=1`);
  await page.waitForFunction(() => window.opspaceReplay && window.opspaceReplay.ready, null, { timeout: 60000 });
  const frames = await page.evaluate(() => window.opspaceReplay.frames);
  check(frames > 10, `the page holds ${frames} frames (more than 10: a replay, not a still)`);

  // Share of the canvas that changes when the robot is hidden, and between two instants.
  const coverage = await page.evaluate(() => {
    const api = window.opspaceReplay;
    const canvas = document.querySelector('#stage canvas');
    const grab = () => {
      const c = document.createElement('canvas');
      c.width = canvas.width;
      c.height = canvas.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(canvas, 0, 0);
      return ctx.getImageData(0, 0, c.width, c.height).data;
    };
    const differing = (a, b) => {
      let n = 0;
      for (let i = 0; i < a.length; i += 4) {
        if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 24) ++n;
      }
      return n / (a.length / 4);
    };
    api.setFrame(0);
    const start = grab();
    api.setRobotVisible(false);
    const empty = grab();
    api.setRobotVisible(true);
    api.setFrame(Math.floor(api.frames / 2));
    const middle = grab();
    api.setFrame(0);
    return { robot: differing(start, empty), motion: differing(start, middle) };
  });
  // The PUMA's links (4-8 cm thick, ~1 m of arm) in a view framed on its motion cover about
  // 4.5 % of a 1200 x 800 canvas; 2 % catches a robot that is missing, shrunk or off screen.
  check(coverage.robot > 0.02, `the robot covers ${(100 * coverage.robot).toFixed(1)} % of the view (> 2 %)`);
  // Half-way through the run the arm has moved: a replay that does not animate changes nothing.
  check(coverage.motion > 0.002, `${(100 * coverage.motion).toFixed(2)} % of the view changes between the first and the middle frame (> 0.2 %)`);

  // Play, pause and the time slider.
  const slider = page.locator('#slider');
  await slider.fill(String(Math.floor(frames / 2)));
  check((await page.locator('#clock').textContent()).startsWith(
    await page.evaluate(() => JSON.parse(document.getElementById('opspace-replay-data').textContent)
      .t[Math.floor(window.opspaceReplay.frames / 2)].toFixed(2))), 'the slider moves the replay to its time');
  const before = await page.locator('#play').textContent();
  await page.locator('#play').click();
  check((await page.locator('#play').textContent()) !== before, `the ${before} button toggles`);
  await page.locator('#play').click();

  await page.evaluate(() => window.opspaceReplay.setFrame(Math.floor(window.opspaceReplay.frames / 3)));
  await page.screenshot({ path: screenshot });
  console.log(`screenshot: ${screenshot}`);
  check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
} finally {
  await browser.close();
}
if (failures.length) {
  console.log(`${failures.length} check(s) failed`);
  process.exit(1);
}
