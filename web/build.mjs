// Bundles the pages' viewers with three.js, each into one minified script:
//   node build.mjs REPLAY_OUTFILE [EXPLORER_OUTFILE]
// src/replay.js for the replay pages, src/explorer.js for the explorer page.
// Run by CMake (target opspace_replay_bundle) after `npm ci` in the build tree.
import { build } from 'esbuild';

const [replay, explorer] = process.argv.slice(2);
if (!replay) {
  console.error('usage: node build.mjs REPLAY_OUTFILE [EXPLORER_OUTFILE]');
  process.exit(2);
}
const pages = [['replay.js', replay]];
if (explorer) pages.push(['explorer.js', explorer]);
for (const [entry, outfile] of pages) {
  await build({
    entryPoints: [new URL(`./src/${entry}`, import.meta.url).pathname],
    bundle: true,
    minify: true,
    format: 'iife',
    target: 'es2020',
    legalComments: 'eof',  // keeps three.js's MIT notice in the page
    outfile,
    logLevel: 'warning',
  });
}
