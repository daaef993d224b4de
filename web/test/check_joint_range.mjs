// The explorer's joint sliders (web/src/joint_range.mjs), checked in node without a browser:
//   node check_joint_range.mjs
// Each expected range follows from the rule the page states: a limit is kept as written, a
// missing one (null in the page data) is one turn, 2 pi rad, or one metre beyond q0.
import assert from 'node:assert/strict';
import { sliderRange } from '../src/joint_range.mjs';

const TURN = 2 * Math.PI;
const cases = [
  // [what, joint, q0, expected range]
  ['a revolute joint with both limits keeps them', { prismatic: false, lower: -2.9, upper: 2.9 }, 0.3, [-2.9, 2.9]],
  ['a continuous joint spans one turn each way from q0', { prismatic: false, lower: null, upper: null }, 0.5,
   [0.5 - TURN, 0.5 + TURN]],
  ['a prismatic joint without limits spans one metre each way', { prismatic: true, lower: null, upper: null }, 0.1,
   [0.1 - 1, 0.1 + 1]],
  ['only the missing side is replaced', { prismatic: false, lower: null, upper: 1.0 }, -0.2, [-0.2 - TURN, 1.0]],
  // A limit of 0 is falsy in JavaScript: `||` instead of `??` would replace it.
  ['a limit of 0 is a limit, not a missing one', { prismatic: true, lower: 0, upper: 0.5 }, 0.2, [0, 0.5]],
  ['an upper limit of 0 too', { prismatic: false, lower: -1.5, upper: 0 }, -0.5, [-1.5, 0]],
];
let failed = 0;
for (const [what, joint, q0, expected] of cases) {
  try {
    assert.deepEqual(sliderRange(joint, q0), expected);
    console.log(`ok      ${what}`);
  } catch (e) {
    failed += 1;
    console.log(`FAILED  ${what}: expected [${expected}], got [${sliderRange(joint, q0)}]`);
  }
}
console.log(`${cases.length - failed} of ${cases.length} slider ranges as the page states`);
process.exit(failed ? 1 : 0);
