// A joint slider's range on the explorer page. The page data writes a missing limit (a
// continuous joint, a prismatic one without bounds) as null (web/explorer/page_data.cpp):
// that side then reaches one turn (revolute) or one metre (prismatic) beyond q0. A limit of 0
// is a limit, which is why the test is on null (??), not on falsiness.
export function sliderRange(joint, q0) {
  const reach = joint.prismatic ? 1 : 2 * Math.PI;
  return [joint.lower ?? q0 - reach, joint.upper ?? q0 + reach];
}
