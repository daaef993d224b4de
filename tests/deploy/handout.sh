#!/usr/bin/env bash
# The student handout from this repository (scripts/handout), each problem's guide in its
# folder, and its README's two commands run inside it as a student would: command 1 grades the
# untouched stubs at 0 of all the points (problems.txt), command 2 passes every test. CI runs
# this after scripts/test (.ci/run).
#   bash tests/deploy/handout.sh REPO WORK
set -euo pipefail
repo=$1 work=$2
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work"
start=$(date +%s)
bash "$repo/scripts/handout" "$work/handout"
cd "$work/handout"
[ "$(git rev-list --count HEAD)" -eq 1 ] || { echo "the handout is not one commit"; exit 1; }
[ -z "$(git status --porcelain)" ] || { echo "the handout's work tree is not clean"; exit 1; }
for gone in solutions tests/mutants tests/tamper docs/instructor.md lib/src/algorithms/pp_robot.cpp problems/1b/grade/graded.cpp problems/1a/grade/answers.hpp grader/suite/grade/reference.cpp; do
  [ ! -e "$gone" ] || { echo "the handout has $gone"; exit 1; }
done
source scripts/problems.sh
for key in "${OPSPACE_KEYS[@]}"; do
  [ -s "problems/$key/guide.md" ] || { echo "the handout has no problems/$key/guide.md"; exit 1; }
done
head -5 README.md | grep -qx 'bash scripts/grade    # installs what is missing, builds, grades your exercises/'
head -6 README.md | grep -qx 'bash scripts/test     # installs what is missing, builds, runs every test (ctest)'

bash scripts/grade > "$work/grade.log" 2>&1 || { tail -40 "$work/grade.log"; echo "README command 1 failed"; exit 1; }
grep -E "^Total: 0 / $OPSPACE_TOTAL points" "$work/grade.log" || { tail -40 "$work/grade.log"; echo "the stubs did not score 0 of $OPSPACE_TOTAL"; exit 1; }
echo "handout: README command 1 graded the untouched stubs at 0 ($(( $(date +%s) - start )) s so far)"
bash scripts/test
echo "handout: README commands 1 and 2 work ($(( $(date +%s) - start )) s)"
