#!/usr/bin/env bash
# A failed simulated test as the student sees it (issue 41): solutions/ with p1b.cpp replaced by
# tests/mutants/p1b_part3_pinv.cpp (PART3 with the pseudo-inverse projector) graded by the real
# grader, then
#   1. the page's figure of "iv. in simulation PART3 holds the tip ..." read from its data
#      attributes: the student's tip error passes the 5 mm bound after 2 s, the reference's (the
#      problem set's law in the same scenario) stays within it. Why each must hold: with J+ the
#      null-space torque leaves Jv^T (Jbar_v - Jv+)^T g on the tip, tens of newtons at these poses
#      (problems/1b/grade/graded.cpp), while the dynamically consistent law leaves none: the reference's
#      tip stays at the mm scale (0.7 mm at most on this scenario), the mutant's moves hundreds;
#   2. the text report names the replay command of that test and ends with "open ...";
#      running the command on hw2-p1 linked with the same file prints the final tip error the
#      figure ends with, to 1e-9 m: the same scenario, law and arithmetic
#      (problems/1b/run/scenario.hpp);
#   3. results.json: valid, under 1 MB, no raw < or > in a text, the test tagged with the mistake
#      the catalogue names and its output holding the run's text table.
# Seen to fail: with the grader of main ("unknown or incomplete argument '--html'"); with
# run_tests' attach_references() call removed (check 1: "the figure has no reference series
# after 2 s"); with hw2-p1-sol, the reference law, as PROGRAM (check 2: its final tip error
# 0.00047 m is not the figure's 0.17691 m); with results.json's tags, then its run tables,
# removed (check 3 names the test).
#   check_report_page.sh GRADER PROGRAM REPO WORK
set -euo pipefail
grader=$1 program=$2 repo=$3 work=$4
test_name="iv. in simulation PART3 holds the tip within 5 mm while q2 follows q_d"
quantity="PART3 tip error |x - x_d|"
seed=41

source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work" exercises out
cp "$repo"/solutions/*.cpp "$work/exercises/"
cp "$repo/tests/mutants/p1b_part3_pinv.cpp" "$work/exercises/p1b.cpp"
"$grader" --unprotected --problem 1b --exercises "$work/exercises" --seed "$seed" --html "$work/page/report.html" \
  --gradescope "$work/results.json" > "$work/report.txt" 2> "$work/grader.err" ||
  fail "the grader exited with $?: $(cat "$work/report.txt" "$work/grader.err")"

# --- 1. the figure, read from its data ------------------------------------------------------------
page=$(tr '\n' ' ' < "$work/page/report.html")
section=${page#*data-test=\"1b $test_name\"}
[ "$section" != "$page" ] || fail "the page has no section for '1b $test_name'"
section=${section%%</section>*}
figure=${section#*data-quantity=\"$quantity\"}
[ "$figure" != "$section" ] || fail "the test's section has no figure of '$quantity'"
figure=${figure%%>*}
attribute() {
  local value=${figure#* data-$1=\"}
  echo "${value%%\"*}"
}
bound=$(attribute bound)
from=$(attribute from)
final=$(attribute final)
# The largest value at or after `from` of the series T (times) V (values).
largest_after() {
  awk -v from="$from" -v times="$1" -v values="$2" 'BEGIN {
    n = split(times, t, " "); split(values, v, " "); m = -1; seen = 0
    for (k = 1; k <= n; ++k) if (t[k] + 0 >= from + 0) { seen = 1; if (v[k] == "NaN" || v[k] + 0 > m) m = (v[k] == "NaN" ? 1e308 : v[k] + 0) }
    if (!seen) { print "none"; exit } printf "%.17g\n", m }'
}
student=$(largest_after "$(attribute student-t)" "$(attribute student-v)")
reference=$(largest_after "$(attribute reference-t)" "$(attribute reference-v)")
[ "$reference" != none ] || fail "the figure has no reference series after $from s"
[ "$student" != none ] || fail "the figure has no student series after $from s"
awk -v s="$student" -v r="$reference" -v b="$bound" 'BEGIN { exit !(s + 0 > b + 0 && r + 0 <= b + 0) }' ||
  fail "expected the student's tip error past the bound $bound m after $from s and the reference's within it: student $student, reference $reference"
echo "ok   the figure: the student's largest tip error after $from s is $student m, past the bound $bound m; the reference's is $reference m"

# --- 2. the replay command ----------------------------------------------------------------------
tail -n 1 "$work/report.txt" | grep -q "^open .*/page/report.html\$" || fail "the text report does not end with 'open .../report.html'"
line=$(grep -F "replay it: bash scripts/run hw2-p1 " "$work/report.txt" | grep -F -- "--test \"$test_name\"" || true)
[ -n "$line" ] || fail "the report names no replay command for '$test_name':$(cat "$work/report.txt")"
arguments=${line#*bash scripts/run hw2-p1 }
eval "set -- $arguments"  # the grader's own text: the part, --test "NAME", --seed N
printf 'ok   replay command: %s\n' "${line#*replay it: }"
OPSPACE_OUT="$work/out" OPSPACE_WATCHDOG=0 "$program" "$@" --no-plots --no-replay > "$work/replay.txt" 2> /dev/null || true
replayed=$(grep -F "final $quantity: " "$work/replay.txt" | sed 's/.*: \([^ ]*\) m$/\1/')
[ -n "$replayed" ] || fail "the replay printed no final '$quantity':$(cat "$work/replay.txt")"
awk -v a="$replayed" -v b="$final" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-9) }' ||
  fail "the replay's final tip error $replayed m differs from the figure's $final m by more than 1e-9"
echo "ok   the replay's final tip error $replayed m is the figure's $final m to 1e-9"

# --- 3. results.json ----------------------------------------------------------------------------
cmake -DJSON="$work/results.json" -DCASE="1b $test_name" -DTAG="mistake: PART3 projects with the pseudo-inverse, like PART2" \
  -P "$repo/tests/graded/check_results_page.cmake" || fail "results.json"
