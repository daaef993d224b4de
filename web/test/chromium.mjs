// What the pages' headless-Chromium checks share (check_*.mjs): the browser with the flags this
// machine needs, a page that collects console errors, the ok/FAIL lines and the run of a check
// from launch to exit status, a page kept offline, and the pixel helpers their in-page code
// calls.
import { existsSync } from 'node:fs';
import { chromium } from 'playwright-core';

/// Debian's Chromium ($CHROMIUM overrides), or exit 77 (ctest SKIP) when it is missing.
export async function launch() {
  const executable = process.env.CHROMIUM || '/usr/bin/chromium';
  if (!existsSync(executable)) {
    console.log(`SKIP: no Chromium at ${executable} (apt-get install chromium; bash scripts/test installs it)`);
    process.exit(77);
  }
  // The flags Chromium needs on a machine with no GPU and a closed network. WebGL then runs on
  // SwiftShader, which Chromium only allows for trusted content when asked to.
  return chromium.launch({
    executablePath: executable,
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--enable-unsafe-swiftshader'],
  });
}

/// A page of `viewport` size and the list its console errors, uncaught errors and failed
/// requests go to.
export async function openPage(browser, viewport) {
  const page = await browser.newPage({ viewport });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()}`));
  return { page, errors };
}

/// check(ok, what) prints an ok/FAIL line and records failures.
export function checker() {
  const failures = [];
  const check = (ok, what) => {
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
    if (!ok) failures.push(what);
  };
  return { check, failures };
}

/// Runs `body({ page, errors, check })` on a page of `viewport` in a browser of its own, closes
/// the browser whatever happens, and ends the process: 0 if every check passed, 1 if one failed
/// (saying how many).
export async function checkInPage(viewport, body) {
  const { check, failures } = checker();
  const browser = await launch();
  try {
    const { page, errors } = await openPage(browser, viewport);
    await body({ page, errors, check });
  } finally {
    await browser.close();
  }
  if (failures.length) console.log(`${failures.length} check(s) failed`);
  process.exit(failures.length ? 1 : 0);
}

/// Lets `page` load `url` and nothing else: every other request is refused, and so counted among
/// its errors (openPage): the page must need nothing but its own file.
export async function offline(page, url) {
  await page.route('**/*', (route) => (route.request().url() === url ? route.continue() : route.abort()));
}

/// Defines, in every document `page` loads from now on, what the checks' in-page code compares
/// pictures with: window.opspaceTest.pixels(canvas), the canvas's RGBA bytes as drawn now (copied
/// through a 2D canvas, which reads a WebGL canvas too), and differs(a, b, i), whether pixel i
/// of two such pictures differs by more than 24 in |dR| + |dG| + |dB| (more than rounding and
/// antialiasing move).
export async function definePixelTools(page) {
  await page.addInitScript(() => {
    window.opspaceTest = {
      pixels(canvas) {
        const c = document.createElement('canvas');
        c.width = canvas.width;
        c.height = canvas.height;
        const ctx = c.getContext('2d');
        ctx.drawImage(canvas, 0, 0);
        return ctx.getImageData(0, 0, c.width, c.height).data;
      },
      differs(a, b, i) {
        return Math.abs(a[4 * i] - b[4 * i]) + Math.abs(a[4 * i + 1] - b[4 * i + 1]) + Math.abs(a[4 * i + 2] - b[4 * i + 2]) > 24;
      },
    };
  });
}
