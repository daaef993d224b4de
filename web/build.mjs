// Bundles the pages' viewers with three.js, each into one minified script:
//   node build.mjs REPLAY_OUTFILE [EXPLORER_OUTFILE [LIVE_OUTFILE]]
// src/replay.js for the replay pages, src/explorer.js for the explorer page, src/live.js for
// the live lab's page (`--live`, docs/live.md).
// Run by CMake (target opspace_replay_bundle) after `npm ci` in the build tree.
import { build } from 'esbuild';

const [replay, explorer, live] = process.argv.slice(2);
if (!replay) {
  console.error('usage: node build.mjs REPLAY_OUTFILE [EXPLORER_OUTFILE [LIVE_OUTFILE]]');
  process.exit(2);
}
const pages = [['replay.js', replay]];
if (explorer) pages.push(['explorer.js', explorer]);
if (live) pages.push(['live.js', live]);
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
