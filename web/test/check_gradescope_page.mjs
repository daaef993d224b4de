// Renders a results.json the way Gradescope shows it to a student (issue 46) in Debian's headless
// Chromium, driven by playwright-core, and checks what survives its HTML sanitizer:
//   node check_gradescope_page.mjs RESULTS.json SCREENSHOT.png [TEST]
// Gradescope does not document its sanitizer beyond "we sanitize the output"; it is a Rails
// application, and Rails' `sanitize` (rails-html-sanitizer's SafeListSanitizer, on Loofah) is the
// documented default there. This page applies that default's safe lists, the strictest of the
// two (docs/grader.md, "In an autograder"): its tags and attributes, Loofah's URI protocols and
// the media types a data: URI may carry. Each test's output goes through it and into the page;
// "html" outputs are inserted as HTML, "text" ones as text.
// Exit 0: no console error or request (the page is offline); the sanitizer removed nothing the
// grader wrote (every element and attribute is on the lists); every failed simulated test (its
// output offers a replay) shows a picture that decodes to a plot 640 px wide; no element of the
// student's (a tag in a text) was rendered. 1: a check failed; 77: no Chromium.
import { readFileSync, writeFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { checkInPage, offline } from './chromium.mjs';

const [results_file, screenshot, focus] = process.argv.slice(2);
if (!results_file || !screenshot) {
  console.error('usage: node check_gradescope_page.mjs RESULTS.json SCREENSHOT.png [TEST]');
  process.exit(2);
}
const results = JSON.parse(readFileSync(results_file, 'utf8'));

// The page: the safe lists, the sanitizer, and the tests to render, as data.
const page_html = `<!DOCTYPE html><html><head><meta charset="utf-8"><title>results.json as Gradescope shows it</title>
<style>body{font-family:sans-serif;max-width:60em;margin:1em auto}section{border-top:1px solid #ccc;padding:.5em 0}pre{white-space:pre-wrap}</style>
</head><body><h1>Autograder results</h1><div id="tests"></div>
<script>
const TAGS = new Set(('strong em b i p code pre tt samp kbd var sub sup dfn cite big small address hr br div span ' +
  'h1 h2 h3 h4 h5 h6 ul ol li dl dt dd abbr acronym a img blockquote del ins').split(' '));
const ATTRIBUTES = new Set('href src width height alt cite datetime title class name xml:lang abbr'.split(' '));
const PROTOCOLS = new Set(('afs aim callto data ed2k feed ftp gopher http https irc line mailto news nntp rsync rtsp ' +
  'sftp ssh tag tel telnet urn webcal xmpp').split(' '));
const DATA_TYPES = new Set(['image/gif', 'image/jpeg', 'image/png', 'image/svg+xml', 'text/css', 'text/plain']);
const removed = [];
function uriAllowed(value) {
  const m = /^\\s*([a-z0-9+.-]+):/i.exec(value);
  if (!m) return true;  // relative
  const protocol = m[1].toLowerCase();
  if (!PROTOCOLS.has(protocol)) return false;
  if (protocol !== 'data') return true;
  const type = /^\\s*data:([^;,]*)/i.exec(value)[1].toLowerCase();
  return DATA_TYPES.has(type);
}
function scrub(node) {
  for (const child of [...node.childNodes]) {
    if (child.nodeType === Node.COMMENT_NODE) { child.remove(); continue; }
    if (child.nodeType !== Node.ELEMENT_NODE) continue;
    const tag = child.tagName.toLowerCase();
    if (!TAGS.has(tag)) {
      removed.push('<' + tag + '>');
      if (tag === 'script' || tag === 'style') child.remove(); else child.replaceWith(...child.childNodes);
      continue;
    }
    for (const a of [...child.attributes]) {
      const ok = ATTRIBUTES.has(a.name) && (!['href', 'src'].includes(a.name) || uriAllowed(a.value));
      if (!ok) { removed.push(tag + '[' + a.name + ']'); child.removeAttribute(a.name); }
    }
    scrub(child);
  }
}
function sanitized(html) {
  const doc = new DOMParser().parseFromString('<body>' + html + '</body>', 'text/html');
  scrub(doc.body);
  return doc.body.innerHTML;
}
const tests = JSON.parse(document.getElementById('data').textContent);
for (const t of tests) {
  const s = document.createElement('section');
  s.dataset.name = t.name;
  s.dataset.status = t.status;
  const h = document.createElement('h3');
  h.textContent = t.name + ' (' + t.score + '/' + t.max_score + ')';
  const out = document.createElement('div');
  out.className = 'output';
  if (t.output_format === 'html') out.innerHTML = sanitized(t.output); else out.textContent = t.output;
  s.append(h, out);
  document.getElementById('tests').append(s);
}
window.removed = removed;
</script></body></html>`;
const data = JSON.stringify(results.tests.map(({ name, status, score, max_score, output, output_format }) =>
  ({ name, status, score, max_score, output, output_format }))).replace(/</g, '\\u003c');
const file = `${screenshot}.page.html`;
writeFileSync(file, page_html.replace('<script>', `<script id="data" type="application/json">${data}</script><script>`));

await checkInPage({ width: 1000, height: 900 }, async ({ page, errors, check }) => {
  const url = pathToFileURL(file).href;
  await offline(page, url);
  await page.goto(url);
  await page.evaluate(() => Promise.all([...document.images].map((i) => i.decode().catch(() => {}))));
  const removed = await page.evaluate(() => window.removed);
  check(removed.length === 0, `the sanitizer kept every element and attribute the grader wrote${removed.length ? `; it removed ${[...new Set(removed)].join(', ')}` : ''}`);
  const shown = await page.$$eval('section', (sections) => sections.map((s) => ({
    name: s.dataset.name,
    failed: s.dataset.status === 'failed',
    simulated: /replay it on your machine/.test(s.textContent),
    pictures: [...s.querySelectorAll('img')].map((i) => ({ width: i.naturalWidth, png: i.src.startsWith('data:image/png;base64,') })),
    foreign: s.querySelectorAll('.output *:not(pre):not(p):not(img)').length,
  })));
  check(shown.length === results.tests.length, `the page shows ${shown.length} of results.json's ${results.tests.length} tests`);
  const failed = shown.filter((t) => t.failed && t.simulated);
  check(failed.length > 0, `${failed.length} failed simulated tests`);
  for (const t of failed) {
    check(t.pictures.length > 0 && t.pictures.every((p) => p.png && p.width === 640),
      `"${t.name}" shows ${t.pictures.length} picture(s) of its run, each a PNG decoded 640 px wide`);
  }
  check(shown.every((t) => t.foreign === 0), 'no element but the grader\'s <pre>, <p> and <img> in any output');
  check(errors.length === 0, `no console error or refused request${errors.length ? `: ${errors.join('; ')}` : ''}`);
  const target = focus ? page.locator(`section[data-name="${focus.replace(/"/g, '\\"')}"]`) : page.locator('body');
  await target.screenshot({ path: screenshot });
});
