#!/bin/bash
# check_missing_members.sh COMPILER SOURCE INCLUDE...: SOURCE (missing_members.cpp) must not
# compile, and the compiler must say which members are missing, by the messages of
# lib/include/opspace/scenarios/scenario_check.hpp. Seen to fail with those checks removed: the
# errors then came from inside the loop (no member named 'clamped_steps').
set -u
compiler=$1 source=$2
shift 2
includes=()
for dir in "$@"; do includes+=("-I$dir"); done
out=$("$compiler" -std=c++17 -fsyntax-only "${includes[@]}" "$source" 2>&1) && { echo "FAIL: $source compiled"; exit 1; }
status=0
for message in "the Goal needs \`double kvj\`" "a Scenario's Summary needs \`clamped_steps\`"; do
  grep -qF "$message" <<< "$out" || { echo "FAIL: no error says: $message"; status=1; }
done
[ $status -eq 0 ] && echo "PASS: the missing members are named" || echo "$out" | grep -E "error" | head -10
exit $status
