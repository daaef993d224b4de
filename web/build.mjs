// Bundles src/replay.js with three.js into one minified script for the replay pages:
//   node build.mjs OUTFILE
// Run by CMake (target opspace_replay_bundle) after `npm ci` in the build tree.
import { build } from 'esbuild';

const outfile = process.argv[2];
if (!outfile) {
  console.error('usage: node build.mjs OUTFILE');
  process.exit(2);
}
await build({
  entryPoints: [new URL('./src/replay.js', import.meta.url).pathname],
  bundle: true,
  minify: true,
  format: 'iife',
  target: 'es2020',
  legalComments: 'eof',  // keeps three.js's MIT notice in the page
  outfile,
  logLevel: 'warning',
});
