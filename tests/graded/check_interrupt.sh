#!/usr/bin/env bash
# An interrupted grading leaves nothing behind: the grader, interrupted while a student's 1b
# controller hangs (Ctrl-C's SIGINT, then timeout's SIGTERM), must end with 128 + the signal,
# say so, and leave no folder of its own in /tmp and no runner running. Its folders carry its
# pid (/tmp/opspace-runners-<pid>-XXXXXX, and -build-, -sandbox-): other gradings on the
# machine have their own. Run alone all the same (ctest RUN_SERIAL).
#   bash check_interrupt.sh GRADER SOLUTIONS HANGING_CASE WORK
set -uo pipefail
grader=$1 solutions=$2 hanging=$3 work=$4
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work" exercises || exit 1
cp "$solutions"/p*.cpp "$work/exercises/"
sed 's/@FAULT@/hang/' "$hanging" > "$work/exercises/p1b.cpp"
# The runners of grader $1: its children running runner-1b (read from /proc: procps may be absent).
runners_of() {
  local stat
  for stat in /proc/[0-9]*/stat; do
    local dir=${stat%/stat} line
    line=$(cat "$stat" 2>/dev/null) || continue
    [ "$(echo "${line##*) }" | cut -d' ' -f2)" = "$1" ] || continue
    tr '\0' ' ' < "$dir/cmdline" 2>/dev/null | grep -q "opspace-runners-.*/runner-1b" && printf '%s ' "${dir#/proc/}"
  done
}
set -m  # background jobs in their own group, with SIGINT not ignored (as in a terminal)
failed=0
for signal in INT TERM; do
  "$grader" --exercises "$work/exercises" --problem 1b > "$work/out-$signal.txt" 2> "$work/err-$signal.txt" &
  pid=$!
  for _ in $(seq 1 600); do
    grep -q "grading problem 1b" "$work/err-$signal.txt" 2>/dev/null && break
    sleep 0.1
  done
  # Once its runner runs, the hanging controller is being asked (slower under the sanitizers).
  runners=""
  for _ in $(seq 1 600); do
    # This grader's own runner (its child): other gradings may run on the machine.
    runners=$(runners_of "$pid")
    [ -n "$runners" ] && break
    sleep 0.1
  done
  sleep 0.5
  kill -"$signal" "$pid"
  wait "$pid"
  code=$?
  sleep 0.5
  left=$(ls -d /tmp/opspace-*-"$pid"-* 2>/dev/null | tr '\n' ' ')
  expected=$((128 + $(kill -l "$signal")))
  still=""
  for runner in $runners; do
    # Killed but not yet reaped by init is dead too: a zombie ('Z') runs nothing.
    state=$(sed -n 's/^[0-9]* (.*) \([A-Z]\).*/\1/p' "/proc/$runner/stat" 2>/dev/null)
    [ -n "$state" ] && [ "$state" != Z ] && still+="$runner "
  done
  echo "SIG$signal: exit $code (expected $expected); runner(s) ${runners:-none} before, ${still:-none} after; new folders in /tmp: ${left:-none}"
  [ -n "$runners" ] || { echo "  no runner was running when the signal was sent: nothing was tested"; failed=1; }
  [ "$code" -eq "$expected" ] || failed=1
  grep -q "interrupted: the programs it started are stopped" "$work/err-$signal.txt" || { echo "  the grader did not say it was interrupted"; failed=1; }
  [ -z "$still" ] || failed=1
  [ -z "$left" ] || failed=1
done
[ "$failed" -eq 0 ] && echo "an interrupted grading stops its runners and leaves no folder in /tmp"
exit "$failed"
