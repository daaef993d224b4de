#!/usr/bin/env bash
# What --seed does to a simulated test (docs/grader.md, "What --seed does in a replay"): nothing.
# solutions/ with p2.cpp replaced by tests/mutants/p2_no_feedforward.cpp (every simulated test
# of problem 2 fails, so each plots both runs) graded twice with --html, under two seeds:
#   1. every simulated test's figures (the student's and the reference's series, the bound, the
#      final value: the figure tags with their data) are the same, byte for byte: the
#      scenarios draw no random input and Bullet's stepping is deterministic;
#   2. the control: the law test's section (its torque table is of a random state the seed
#      draws) differs, so check 1 compares what a seed would change;
#   3. the replay program prints the same final values under both seeds.
#   check_seed_simulated.sh GRADER PROGRAM REPO WORK
# PROGRAM: hw2-p2-sol (a replay's final values do not depend on the controller's correctness).
# Seen to fail: check 1 with the second grading's p2.cpp the reference's (a run that does change:
# "the figures ... differ under seeds 41 and 42"); check 2 with the same seed twice ("the same
# under seeds 41 and 41"). No simulated test can be made to draw from the seed here without
# editing problems/*/grade/graded.cpp: check 1 is the guard that one day fails if one does.
set -euo pipefail
grader=$1 program=$2 repo=$3 work=$4
seeds=(41 42)  # any two seeds
simulated="d. in simulation link7's origin follows the desired position within 1 mm RMS after 1 s"
law="c. the controller applies J0^T"

source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work" exercises
cp "$repo"/solutions/*.cpp "$work/exercises/"
cp "$repo/tests/mutants/p2_no_feedforward.cpp" "$work/exercises/p2.cpp"
for seed in "${seeds[@]}"; do
  "$grader" --unprotected --problem 2 --exercises "$work/exercises" --seed "$seed" --html "$work/$seed.html" \
    > "$work/$seed.txt" 2>&1 || fail "the grader exited with $?: $(cat "$work/$seed.txt")"
done

# section SEED PREFIX: the page's section of the test whose name starts with PREFIX, on one line
# (the name as the page writes it: ' as &#39;).
section() {
  local page prefix=${2//\'/"&#39;"}
  page=$(tr '\n' ' ' < "$work/$1.html")
  local s=${page#*data-test=\"2 "$prefix"}
  [ "$s" != "$page" ] || fail "the page of seed $1 has no test '$2'"
  echo "${s%%</section>*}"
}
# figures SEED PREFIX: the section's figure tags, their data attributes included.
figures() {
  section "$1" "$2" | grep -o '<figure class="run"[^>]*>' || fail "'$2' has no figure under seed $1"
}

a=$(figures "${seeds[0]}" "$simulated")
b=$(figures "${seeds[1]}" "$simulated")
[ "$a" = "$b" ] || fail "the figures of '$simulated' differ under seeds ${seeds[0]} and ${seeds[1]}"
echo "ok   the figures of '$simulated' are the same under seeds ${seeds[0]} and ${seeds[1]} (${#a} characters of data)"

[ "$(section "${seeds[0]}" "$law")" != "$(section "${seeds[1]}" "$law")" ] ||
  fail "the law test's section is the same under seeds ${seeds[0]} and ${seeds[1]}: the seed changed nothing to compare"
echo "ok   the law test's random states differ under the two seeds"

replay() {
  OPSPACE_OUT="$work/out-$1" OPSPACE_WATCHDOG=0 "$program" --test "$simulated" --seed "$1" --no-plots --no-replay 2> /dev/null |
    grep '^final ' || true
}
first=$(replay "${seeds[0]}")
second=$(replay "${seeds[1]}")
[ -n "$first" ] || fail "the replay printed no final value"
[ "$first" = "$second" ] || fail "the replay's final values differ under two seeds:
$first
---
$second"
echo "ok   the replay prints the same final values under both seeds: $(echo "$first" | head -n 1)"
