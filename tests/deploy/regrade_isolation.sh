#!/usr/bin/env bash
# scripts/regrade grades two students at once, as Gradescope would grade them apart: alice,
# hostile (tests/deploy/hostile/p1b_neighbour.cpp.in: her 1b runner keeps busy as many of the 40
# processes it tries as it may start, and writes over every file of another grading it can
# reach), and bob, the reference. Each grading
# runs its student's code as an account of its own, in its own view of the files, and a test's
# limit counts the runner's CPU time: bob keeps full marks under the issue's 10 s limit (before the
# third round he lost 7 points to "did not answer within 10 s"), his files and row are his, and
# nothing alice wrote landed (no pwned-* marker). Alice's other problems keep full marks: her
# processes die with her 1b runner.
#   bash tests/deploy/regrade_isolation.sh REPO WORK [SECONDS PER TEST, 10]
set -euo pipefail
repo=$1 work=$2 limit=${3:-10}
check="$repo/tests/deploy/check_json.cmake"
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
skip_unless_stubs_untouched
fresh_work "$work" in/alice in/bob out
cp "$repo"/solutions/p*.cpp "$work/in/alice/"
cp "$repo"/solutions/p*.cpp "$work/in/bob/"
out="$(cd "$work/out" && pwd)"
{ sed "s#@OUT@#$out#g" "$repo/tests/deploy/hostile/p1b_neighbour.cpp.in"; cat "$repo/solutions/p1b.cpp"; } > "$work/in/alice/p1b.cpp"

bash "$repo/scripts/regrade" "$work/in" "$work/out" --jobs 2 -- --timeout "$limit" 2> "$work/regrade.err" || { cat "$work/regrade.err"; exit 1; }
cat "$work/regrade.err"
cat "$work/out/gradebook.csv"
# Full marks: each problem's points and the total, from the list (problems.txt); alice's 1b is
# the list's second column.
full=$(IFS=,; echo "${OPSPACE_POINTS[*]}")
[ "${OPSPACE_KEYS[1]}" = 1b ] || { echo "problems.txt's second problem is not 1b: update this test"; exit 1; }
grep -qx "bob,$full,$OPSPACE_TOTAL,$OPSPACE_TOTAL," "$work/out/gradebook.csv" ||
  { grep -E 'FAIL|not graded|!' "$work/out/bob/report.txt" | head -20; echo "bob did not keep full marks beside alice"; exit 1; }
alice_others="${OPSPACE_POINTS[0]},[0-9.]*,$(IFS=,; echo "${OPSPACE_POINTS[*]:2}")"
grep -q "^alice,$alice_others," "$work/out/gradebook.csv" || { echo "alice's other problems lost points to her own 1b"; exit 1; }
cmake -DJSON="$work/out/bob/results.json" -DFULL=ALL -P "$check"
if ls "$work/out"/pwned-* > /dev/null 2>&1; then
  ls "$work/out"/pwned-*
  echo "alice's code wrote over another grading's files"
  exit 1
fi
cmp -s "$repo/solutions/p1a.cpp" "$work/out/bob/exercises/p1a.cpp" || { echo "bob's collected files changed"; exit 1; }
grep -q 'UNPROTECTED' "$work/out/gradebook.csv" && { echo "the gradebook says UNPROTECTED where the sandbox holds"; exit 1; }
echo "a hostile submission graded beside an honest one changed nothing of his"
