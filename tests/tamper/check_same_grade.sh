#!/usr/bin/env bash
# The same grade whatever process answers (issue 58, docs/grader.md "A second runner"): one problem
# of the reference solutions, its file replaced by CASE (cases/, @FAULT@ set to FAULT), graded
# under one seed with --jobs 1, with --jobs 2 (a second runner makes some of its runs) and with
# --jobs 2 --one-runner must earn the same points in every test, and give the same report and
# results.json (but its times), however the file tells its processes apart.
#   bash tests/tamper/check_same_grade.sh GRADER SOLUTIONS CASE FAULT PROBLEM WORK
# Seen to fail before every run had a process of its own (seed 58): process_history.cpp's "first"
# earned PART3's test (4 points) with --jobs 2 and 0 with one runner; "count" 17 and 13 (PART3's
# run made after PART1's on one runner, answered wrong from about its 5 000th tick on).
set -euo pipefail
grader=$1 solutions=$2 case=$3 fault=$4 problem=$5 work=$6
seed=58  # any seed: the three gradings draw the same inputs from it

source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work" exercises
cp "$solutions"/p*.cpp "$work/exercises/"
target=p${problem}.cpp
sed "s/@FAULT@/$fault/g" "$case" > "$work/exercises/$target"

for how in jobs1 jobs2 one_runner; do
  case $how in
    jobs1) options=(--jobs 1) ;;
    jobs2) options=(--jobs 2) ;;
    one_runner) options=(--jobs 2 --one-runner) ;;
  esac
  "$grader" --exercises "$work/exercises" --problem "$problem" --seed "$seed" "${options[@]}" --cache "$work/cache" \
    --gradescope "$work/$how.json" > "$work/$how.txt" 2> "$work/$how.err" ||
    fail "the grader exited with $? ($how): $(cat "$work/$how.txt" "$work/$how.err")"
done
# Problems that list runs ahead (1b) must have had them made by a second runner with --jobs 2,
# else the case compares one runner with itself.
if [ "$problem" = 1b ]; then
  grep -q "^a second runner makes" "$work/jobs2.err" || fail "no second runner with --jobs 2: $(cat "$work/jobs2.err")"
fi
grep -q "second runner" "$work/one_runner.err" && fail "a second runner with --one-runner"

# Each test's name and score, one a line, from results.json.
scores() {
  python3 -c 'import json, sys
for t in json.load(open(sys.argv[1]))["tests"]: print(t["score"], t["name"])' "$work/$1.json"
}
report() { grep -v -e '^Built in ' -e '^results.json: ' "$work/$1.txt"; }
json() { sed -E 's/"execution_time": *[0-9.eE+-]+/"execution_time": T/' "$work/$1.json"; }
for how in jobs2 one_runner; do
  [ "$(scores jobs1)" = "$(scores "$how")" ] ||
    fail "$fault: the scores differ between --jobs 1 and $how: $(diff <(scores jobs1) <(scores "$how"))"
  [ "$(report jobs1)" = "$(report "$how")" ] ||
    fail "$fault: the reports differ between --jobs 1 and $how: $(diff <(report jobs1) <(report "$how") | head -20)"
  [ "$(json jobs1)" = "$(json "$how")" ] ||
    fail "$fault: results.json differs between --jobs 1 and $how: $(diff <(json jobs1) <(json "$how") | head -c 2000)"
done
echo "ok   $fault: the same scores, report and results.json with --jobs 1, --jobs 2 and --one-runner ($(grep '^Total: ' "$work/jobs1.txt"))"
