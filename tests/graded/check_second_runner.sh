#!/usr/bin/env bash
# A second runner (issue 50, docs/grader.md "A second runner") changes no grade: problem 1b graded
# alone with --jobs 2, where a second runner makes PART3's run while the tests run, and with
# --one-runner, under one seed, gives the same report, results.json (but its execution_time) and
# page, byte for byte, for:
#   mutant   tests/mutants/p1b_part3_pinv.cpp: the diagnosis of PART3's simulated test reads the
#            calls of the run the second runner made ("likely mistake: ..." on that test);
#   crash    solutions/p1b.cpp whose controller prints a line one second into each part's run and
#            crashes two seconds into PART3's: the prints land on the test that made each run and
#            the crash costs PART3's tests only (PART1's passes, the four law tests pass);
#   hang     the same, hanging instead of crashing, with a 2 s limit: the same, with the limit.
#   check_second_runner.sh GRADER REPO WORK
# Seen to fail: with the recording not given to the test (runs_ahead.cpp give(): "the reports
# differ", the PART3 test's diagnosis became "likely the same mistake as above"); with the prints
# not taken (RunnerProcess::take_run: "the reports differ", PART3's line missing); with the
# failure not taken (the PART3 test not interrupted: "the reports differ").
set -euo pipefail
grader=$1 repo=$2 work=$3
seed=50  # any seed: both gradings draw the same inputs from it

source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work"
part3="iv. in simulation PART3 holds the tip within 5 mm"
part1="ii. in simulation PART1 brings the tip to x_d"
drift="iii. in simulation the PART2 tip drifts"

# faulty FAULT: the reference's law, printing one second into each simulated run and doing FAULT
# (crash or hang) two seconds into PART3's. A simulated run's ticks fall on the 1 ms grid from
# t = 0; a law test's random states have t drawn uniformly in [0, 10] s, off that grid (they
# would have to hit it within 1e-6 of a step), so law tests never print nor fail.
faulty() {
  sed 's/^Vector6d control(Part part, const State& s, const Goal& goal) {/Vector6d law(Part part, const State\& s, const Goal\& goal) {/' \
    "$repo/solutions/p1b.cpp" | sed 's|^}  // namespace opspace::hw2::p1b||'
  cat <<CODE
}  // namespace opspace::hw2::p1b
#include <cmath>
#include <cstdio>
namespace opspace::hw2::p1b {
Vector6d control(Part part, const State& s, const Goal& goal) {
  const double ms = std::round(s.t * 1000.0);
  if (std::abs(s.t * 1000.0 - ms) < 1e-6) {
    if (ms == 1000.0) std::fprintf(stderr, "part %d one second in\n", static_cast<int>(part));
    if (ms == 2000.0 && part == Part::kDynamicallyConsistentNullspace) {
      if ("$1" == std::string("crash")) {
        volatile double* nowhere = nullptr;
        nowhere[static_cast<int>(s.t)] = 1.0;  // writes through a null pointer
      }
      for (volatile unsigned long spin = 0; spin != 1; spin = spin + 2) {
      }
    }
  }
  return law(part, s, goal);
}
}  // namespace opspace::hw2::p1b
CODE
}

# grade CASE FILE [OPTION...]: problem 1b of solutions/ with FILE as p1b.cpp, with and without
# the second runner; the two gradings' report, results.json and page must be the same.
grade() {
  local case=$1 file=$2
  shift 2
  mkdir -p "$work/$case/exercises"
  cp "$repo"/solutions/*.cpp "$work/$case/exercises/"
  cp "$file" "$work/$case/exercises/p1b.cpp"
  local how
  for how in two one; do
    local one=()
    [ "$how" = one ] && one=(--one-runner)
    "$grader" --unprotected --exercises "$work/$case/exercises" --problem 1b --seed "$seed" --jobs 2 "${one[@]}" "$@" \
      --cache "$work/cache" --gradescope "$work/$case/$how.json" --html "$work/$case/$how.html" \
      > "$work/$case/$how.txt" 2> "$work/$case/$how.err" ||
      fail "$case: the grader exited with $? ($how): $(cat "$work/$case/$how.txt" "$work/$case/$how.err")"
  done
  grep -q "^a second runner makes 1 of problem 1b's 3 simulated runs" "$work/$case/two.err" ||
    fail "$case: no second runner with --jobs 2: $(cat "$work/$case/two.err")"
  grep -q "second runner" "$work/$case/one.err" && fail "$case: a second runner with --one-runner"
  report() { grep -v -e '^Built in ' -e '^results.json: ' -e "^the report's page: " -e '^open ' "$work/$case/$1.txt"; }
  json() { sed -E 's/"execution_time": *[0-9.eE+-]+/"execution_time": T/' "$work/$case/$1.json"; }
  [ "$(report one)" = "$(report two)" ] || fail "$case: the reports differ: $(diff <(report one) <(report two) | head -20)"
  [ "$(json one)" = "$(json two)" ] || fail "$case: results.json differs: $(diff <(json one) <(json two) | head -c 2000)"
  cmp -s "$work/$case/one.html" "$work/$case/two.html" ||
    fail "$case: the pages differ: $(cmp "$work/$case/one.html" "$work/$case/two.html")"
  echo "ok   $case: the same report, results.json and page with and without the second runner ($(grep '^Total: ' "$work/$case/two.txt"))"
}

# block CASE TITLE: the report's lines of the test whose title starts with TITLE, up to the next test.
block() {
  awk -v title="$2" 'index($0, title) { on = 1; print; next } on && /^ *(PASS|FAIL|PART|FAILED|[0-9])/ { exit } on' \
    "$work/$1/two.txt"
}

grade mutant "$repo/tests/mutants/p1b_part3_pinv.cpp"
block mutant "$part3" | grep -q "likely mistake: PART3 projects with the pseudo-inverse" ||
  fail "mutant: the PART3 test names no mistake of its own: $(block mutant "$part3")"
echo "ok   mutant: the PART3 test's diagnosis reads the run the second runner made"

faulty crash > "$work/crash.cpp"
grade crash "$work/crash.cpp"
block crash "$part3" | grep -q "crashed: Segmentation fault.* during this test" ||
  fail "crash: the PART3 test was not interrupted by the crash: $(block crash "$part3")"
block crash "$part3" | grep -q "part 3 one second in" || fail "crash: PART3's print is not on its test: $(block crash "$part3")"
block crash "$part1" | grep -q "part 1 one second in" || fail "crash: PART1's print is not on its test: $(block crash "$part1")"
block crash "$drift" | grep -q "part 2 one second in" || fail "crash: PART2's print is not on the drift test: $(block crash "$drift")"
block crash "$drift" | grep -q "part 3" && fail "crash: PART3's print is on the drift test too: $(block crash "$drift")"
grep -q "^Total: 13 / 20 points" "$work/crash/two.txt" || fail "crash: not 13 / 20 (the law tests' 10 and PART1's 3): $(cat "$work/crash/two.txt")"
echo "ok   crash: each print on the test that made its run; the crash costs PART3's two tests only"

faulty hang > "$work/hang.cpp"
grade hang "$work/hang.cpp" --timeout 1b=2
block hang "$part3" | grep -q "did not answer within" || fail "hang: the PART3 test did not time out: $(block hang "$part3")"
grep -q "^Total: 13 / 20 points" "$work/hang/two.txt" || fail "hang: not 13 / 20: $(cat "$work/hang/two.txt")"
echo "ok   hang: the hang costs PART3's two tests only"
