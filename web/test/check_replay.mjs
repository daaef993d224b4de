// Loads a replay page in Debian's headless Chromium (driven by playwright-core) and checks
// that a person would see the robot move:
//   node check_replay.mjs PAGE.html SCREENSHOT.png [MIN_ROBOT_SHARE]
// MIN_ROBOT_SHARE (default 0.02) is the share of the view the robot must cover: it depends on
// the robot, so each test passes its own (tests/vis/CMakeLists.txt says why).
// Exit 0: the page loaded without console errors, play/pause and the slider work, the robot
// covers part of the view and moves; 1: a check failed; 77: no Chromium (ctest SKIP).
import { pathToFileURL } from 'node:url';
import { checkInPage, definePixelTools } from './chromium.mjs';

const [page_file, screenshot, share_arg = '0.02'] = process.argv.slice(2);
const min_robot_share = Number(share_arg);
if (!page_file || !screenshot || !(min_robot_share > 0 && min_robot_share < 1)) {
  console.error('usage: node check_replay.mjs PAGE.html SCREENSHOT.png [MIN_ROBOT_SHARE, between 0 and 1]');
  process.exit(2);
}

await checkInPage({ width: 1200, height: 800 }, async ({ page, errors, check }) => {
  await definePixelTools(page);
  await page.goto(`${pathToFileURL(page_file).href}#t=1`);
  await page.waitForFunction(() => window.opspaceReplay && window.opspaceReplay.ready, null, { timeout: 60000 });
  const frames = await page.evaluate(() => window.opspaceReplay.frames);
  check(frames > 10, `the page holds ${frames} frames (more than 10: a replay, not a still)`);

  // The robot's pixels at an instant: those that change when the robot is hidden. Its share
  // of the canvas, and how much of it moves between the first and the middle frame. Markers
  // (a moving target, growing trails) are drawn in both pictures of an instant, so they do
  // not count as the robot, nor as its motion.
  const coverage = await page.evaluate(() => {
    const api = window.opspaceReplay;
    const canvas = document.querySelector('#stage canvas');
    const grab = () => window.opspaceTest.pixels(canvas);
    // Pixel by pixel: does the robot show there (its colour differs from the scene without it)?
    const robotAt = (frame) => {
      api.setFrame(frame);
      const shown = grab();
      api.setRobotVisible(false);
      const hidden = grab();
      api.setRobotVisible(true);
      const mask = new Uint8Array(shown.length / 4);
      for (let i = 0; i < mask.length; ++i) mask[i] = window.opspaceTest.differs(shown, hidden, i) ? 1 : 0;
      return mask;
    };
    const start = robotAt(0);
    const middle = robotAt(Math.floor(api.frames / 2));
    api.setFrame(0);
    let inStart = 0, inEither = 0, inOne = 0, onBorder = 0;
    const w = canvas.width, h = canvas.height;
    for (let i = 0; i < start.length; ++i) {
      inStart += start[i];
      inEither += start[i] | middle[i];
      inOne += start[i] ^ middle[i];
      const x = i % w, y = Math.floor(i / w);
      if ((x === 0 || y === 0 || x === w - 1 || y === h - 1) && (start[i] | middle[i])) ++onBorder;
    }
    return { robot: inStart / start.length, motion: inEither ? inOne / inEither : 0, onBorder };
  });
  check(coverage.robot > min_robot_share,
    `the robot covers ${(100 * coverage.robot).toFixed(1)} % of the view (> ${(100 * min_robot_share).toFixed(1)} %)`);
  // The view is framed on the run (the camera keeps a margin around the bodies and markers), so
  // at neither instant does the robot touch the edge of the canvas: a robot cut off is partly
  // unseen (the 3R arm's forearm was, before markers were framed too).
  check(coverage.onBorder === 0,
    `the whole robot is in view (${coverage.onBorder} of its pixels on the edge of the canvas, none allowed)`);
  // Half-way through the run the arm has moved: of the pixels the robot covers at the start or
  // in the middle, more than 5 % are covered at one instant only. A robot held still scores 0
  // whatever its markers do (a trail crossing it changes well under 1 %); each test's run moves
  // its arm by a good part of its own size by then (tests/vis/CMakeLists.txt).
  check(coverage.motion > 0.05,
    `${(100 * coverage.motion).toFixed(1)} % of the robot's pixels change between the first and the middle frame (> 5 %)`);

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
});
