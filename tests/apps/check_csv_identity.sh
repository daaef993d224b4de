#!/usr/bin/env bash
# check_csv_identity.sh APPS_DIR ORACLE WORK: every CSV log the four -sol programs write in
# their default runs (each PART of hw2-p1 and its compare, hw2-p2, hw2-p3, both targets of hw2-p4
# with the plain law) and in one run of another duration must be byte-identical to the log
# closed-loop-oracle writes of the same run by its own path (closed_loop_oracle.cpp). A change
# in the programs' loop, rows or writer changes some byte and fails here; the oracle shares
# with them only the library's simulation, observers, goals and solutions/. Both come from the
# same build (same compiler, same flags: no -march, so x86-64 contracts no a*b+c into an FMA
# that could round one expression differently in the two places); the oracle's rows repeat the
# scenarios' expressions operation for operation, so equal inputs print equal digits.
set -euo pipefail
apps="$1" oracle="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
failures=0
# same PROGRAM_CSV PROBLEM RUN SECONDS: the program's log against the oracle's.
same() {
  local log="$1" problem="$2" run="$3" seconds="$4"
  local expected="$work/oracle-$(basename "$log")"
  "$oracle" "$problem" "$run" "$seconds" "$expected"
  if [ ! -s "$log" ]; then
    echo "FAIL: $log was not written"
    failures=$((failures + 1))
  elif cmp "$log" "$expected"; then
    echo "same: $(basename "$log") ($(wc -l < "$log") lines), problem $problem $run over $seconds s"
  else
    echo "FAIL: $log differs from the oracle's $expected (problem $problem $run over $seconds s)"
    failures=$((failures + 1))
  fi
}
# program NAME ARGS...: runs the build's program NAME with ARGS, its outputs in $work/out.
program() {
  local name="$1"
  shift
  OPSPACE_OUT="$work/out" "$apps/$name" "$@" --no-plots --no-replay > "$work/$name.stdout" 2> "$work/$name.stderr" ||
    { echo "FAIL: $name $* exited with $?"; cat "$work/$name.stderr"; exit 1; }
}
out="$work/out"
program hw2-p1-sol 1
same "$out/hw2-p1-sol-part1.csv" 1b 1 10
program hw2-p1-sol 1 --no-joint-damping
same "$out/hw2-p1-sol-part1-no-damping.csv" 1b 1-no-damping 10
program hw2-p1-sol 2
same "$out/hw2-p1-sol-part2.csv" 1b 2 10
program hw2-p1-sol 3
same "$out/hw2-p1-sol-part3.csv" 1b 3 10
program hw2-p1-sol compare
same "$out/hw2-p1-sol-compare-part2.csv" 1b 2 10
same "$out/hw2-p1-sol-compare-part3.csv" 1b 3 10
program hw2-p2-sol
same "$out/hw2-p2-sol.csv" 2 - 10
program hw2-p3-sol
same "$out/hw2-p3-sol.csv" 3 - 10
program hw2-p4-sol
for target in z y; do
  same "$out/hw2-p4-sol-$target.csv" 4 "$target" 3
  same "$out/hw2-p4-sol-$target-plain.csv" 4 "$target-plain" 3
done
program hw2-p2-sol --duration 2.5 --csv "$out/p2-short.csv"
same "$out/p2-short.csv" 2 - 2.5
[ "$failures" -eq 0 ] || { echo "$failures logs differ"; exit 1; }
echo "every log is the oracle's, byte for byte"
