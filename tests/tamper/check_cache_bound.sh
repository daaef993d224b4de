#!/usr/bin/env bash
# A cache-filling submission: a p1a.cpp carrying a 48 MiB array (kept by the linker: `retain`),
# graded in three variants, each a new runner of 48 MiB, under a 100 MiB bound (two fit, three
# do not). The runners' cache stays under its bound after every grading, the least recently
# used runner is the one removed (A, B, A again, then C: B goes, A stays), and the log says so.
#   bash tests/tamper/check_cache_bound.sh GRADER SOLUTIONS STUBS WORK
set -euo pipefail
grader=$1 solutions=$2 stubs=$3 work=$4
bound_mib=100
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work"

# Variant NAME: the reference's p1a with its own 48 MiB array, the other files the stubs.
variant() {
  mkdir -p "$work/$1"
  cp "$stubs"/p*.cpp "$work/$1/"
  { echo "__attribute__((used, retain)) static const char pad_$1[48 << 20] = {1};"; cat "$solutions/p1a.cpp"; } > "$work/$1/p1a.cpp"
}
# Grades variant $1; checks the cache's runners against the bound; prints the grader's log.
grade() {
  "$grader" --exercises "$work/$1" --problem 1a --cache "$work/cache" --cache-limit "$bound_mib" > "$work/$1.out" 2>&1 ||
    { cat "$work/$1.out"; fail "the grader failed on variant $1"; }
  grep -q '^Total: 23 / 23' "$work/$1.out" || { cat "$work/$1.out"; fail "variant $1 lost points: its padding is not a mistake"; }
  local bytes
  bytes=$(find "$work/cache" -maxdepth 1 -name 'runner-*' -printf '%s\n' | awk '{ s += $1 } END { print s + 0 }')
  [ "$bytes" -le $((bound_mib << 20)) ] || fail "after variant $1 the cache holds $bytes bytes, over its $bound_mib MiB bound"
  grep '^runner cache: ' "$work/$1.out" || fail "variant $1's log does not give the cache's size"
}
reused() { grep -q 'exercises/p1a.cpp: unchanged since it was last built' "$work/$1.out"; }

for v in A B C; do variant "$v"; done
grade A
grade B
cp -r "$work/A" "$work/A2"
grade A2
reused A2 || fail "variant A, graded again, was not reused from the cache"
grade C
grep -q 'least recently used removed' "$work/C.out" || fail "C's grading removed nothing, or did not say so"
cp -r "$work/A" "$work/A3"
cp -r "$work/B" "$work/B2"
grade A3
reused A3 || fail "A, used more recently than B, was removed"
grade B2
reused B2 && fail "B, the least recently used, was kept"
[ -z "$(find "$work/cache" -maxdepth 1 -name 'held-*')" ] || fail "a grading left its links to the runners behind"
echo "the cache stayed under its $bound_mib MiB bound, removing the least recently used runner"
