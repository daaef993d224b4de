#!/usr/bin/env bash
# The visible suite compares directions as subspaces: the reference's p4.cpp with its singular
# directions given in another orthonormal basis (rotated by 45 degrees within the subspace,
# signs flipped) earns full marks; with a wrong subspace (the first columns of the identity)
# it loses the tests that ask for them, and the finding names the function.
#   bash tests/deploy/visible_bases.sh GRADER SOLUTIONS WORK
set -euo pipefail
grader=$1 solutions=$2 work=$3
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work" right wrong
check="$(dirname "${BASH_SOURCE[0]}")/check_json.cmake"

variant() {  # variant DIR BODY: the reference with singular_directions wrapped by BODY
  cp "$solutions"/p*.cpp "$1/"
  sed -i 's/^Directions singular_directions(const Kinematics& k) {$/Directions reference_singular_directions(const Kinematics\& k) {/' "$1/p4.cpp"
  grep -q reference_singular_directions "$1/p4.cpp" || { echo "solutions/p4.cpp changed: update this test"; exit 1; }
  printf '\nnamespace opspace::hw2::p4 {\nDirections singular_directions(const Kinematics& k) {\n  Directions d = reference_singular_directions(k);\n%s\n  return d;\n}\n}  // namespace opspace::hw2::p4\n' "$2" >> "$1/p4.cpp"
}
variant "$work/right" '  if (d.count == 2) {
    const Eigen::Vector3d a = d.u.col(0), b = d.u.col(1);
    d.u.col(0) = -(a + b) / std::sqrt(2.0);
    d.u.col(1) = (a - b) / std::sqrt(2.0);
  } else if (d.count == 1) {
    d.u.col(0) = -d.u.col(0);
  }'
variant "$work/wrong" '  d.u = Eigen::Matrix3d::Zero();
  d.u.leftCols(d.count) = Eigen::Matrix3d::Identity().leftCols(d.count);'

"$grader" --exercises "$work/right" --gradescope "$work/right.json" > "$work/right.log"
cmake -DJSON="$work/right.json" -DFULL=ALL -P "$check"
"$grader" --exercises "$work/wrong" --gradescope "$work/wrong.json" > "$work/wrong.log"
others=()  # every problem but 4
for key in "${OPSPACE_KEYS[@]}"; do [ "$key" = 4 ] || others+=("$key"); done
cmake -DJSON="$work/wrong.json" "-DFULL=$(IFS=';'; echo "${others[*]}")" -P "$check"
grep -q 'singular_directions, recorded call' "$work/wrong.json" || { echo "the wrong subspace was not caught"; cat "$work/wrong.log"; exit 1; }
grep -q "^Total: $OPSPACE_TOTAL / $OPSPACE_TOTAL" "$work/wrong.log" && { echo "the wrong subspace earned full marks"; exit 1; }
echo "any basis of the right subspace passes; a wrong subspace fails"
