// What the pages' headless-Chromium checks share (check_replay.mjs, check_explorer.mjs): the
// browser with the flags this machine needs, a page that collects console errors, and the
// ok/FAIL lines.
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
