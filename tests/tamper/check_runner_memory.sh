#!/usr/bin/env bash
# A runner that takes more memory than its grading's budget: p1a's mass_matrix fills 768 MiB
# (under a runner's own 1 GiB of address space) in a grading whose budget is 512 MiB (about
# twice what compiling an exercise file takes, 270 MB). Where the kernel offers a memory group,
# the kernel stops the runner at the budget and the report names it; elsewhere the budget caps
# the runner's address space and its allocation fails. Either way the tests of that call are
# lost, the grader records no fault of its own and the others' answers keep their points.
#   bash tests/tamper/check_runner_memory.sh GRADER SOLUTIONS WORK
set -euo pipefail
grader=$1 solutions=$2 work=$3
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work" ex
cp "$solutions"/p*.cpp "$work/ex/"
# The reference's p1a, its mass_matrix first touching every page of 768 MiB.
{
  echo '#include <cstdlib>'
  echo '#include <cstring>'
  echo 'char* volatile g_kept;  // escapes, so the compiler keeps the allocation and its writes'
  sed 's/^Eigen::Matrix2d mass_matrix(double m1, double m2) {$/&\n  g_kept = static_cast<char*>(std::malloc(768u << 20));\n  if (g_kept) std::memset(g_kept, 1, 768u << 20);/' \
    "$solutions/p1a.cpp"
} > "$work/ex/p1a.cpp"
grep -q 'memset' "$work/ex/p1a.cpp" || fail "the case did not patch mass_matrix (has solutions/p1a.cpp changed?)"
"$grader" --exercises "$work/ex" --problem 1a --memory 512 --cache "$work/cache" --gradescope "$work/results.json" \
  > "$work/report.txt" 2>&1 || { cat "$work/report.txt"; fail "the grader failed"; }
cat "$work/report.txt"
grep -q 'FAIL  0/3   ii. the mass matrix' "$work/report.txt" || fail "the mass matrix test was not lost"
grep -q '"grader_faults" *: *0' "$work/results.json" || fail "the grader counted the runner's memory as its own fault"
if "$grader" --check-sandbox --memory 512 | grep -q '^memory budget: a group per grading'; then
  grep -q "your code used more than this grading's memory budget of 512 MiB (the kernel stopped it)" "$work/report.txt" ||
    fail "the report does not name the grading's memory budget"
fi
grep -q 'PASS  3/3   v. the weighted inverse' "$work/report.txt" || fail "the tests that do not call mass_matrix lost points"
echo "the runner was stopped at its grading's memory budget; only its tests were lost"
