#!/usr/bin/env bash
# A memory-hungry compile beside an honest classmate, in one regrade (issue 47): dave's p1b.cpp
# concatenates a 4 GiB string literal (macros doubling it; the compiler holds about three
# times a literal's size), carol's is the reference. Two at a time with 2048 MiB between them,
# each grading has a budget of 1024 MiB, four times the 270 MB the reference's compile takes.
# Where the kernel offers a memory group, dave's compile is stopped at his budget and his
# report says so; everywhere, carol keeps 20 / 20. Her time beside dave and alone (each with a
# fresh cache, so both compile) is printed, not judged: a timed bound failed here under other
# engineers' load, and speed is a benchmark's question. Starving her (her compile killed, or
# her runs past their time limits) costs her points, which the 20 / 20 check sees.
#   bash tests/deploy/regrade_memory.sh REPO GRADER WORK
set -euo pipefail
repo=$1 grader=$2 work=$3
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
skip_unless_stubs_untouched
fresh_work "$work" in/carol in/dave alone
cp "$repo/solutions/p1b.cpp" "$work/in/carol/"
{
  printf '#define X0 "%s"\n' "$(head -c 1000 /dev/zero | tr '\0' a)"
  for i in $(seq 1 11); do echo "#define X$i X$((i - 1)) X$((i - 1)) X$((i - 1)) X$((i - 1))"; done
  echo 'const char* big = X11;'
} > "$work/in/dave/p1b.cpp"

# carol alone: her execution time, from her results.json.
cp "$repo"/exercises/p*.cpp "$work/alone/"
cp "$repo/solutions/p1b.cpp" "$work/alone/"
"$grader" --exercises "$work/alone" --problem 1b --cache "$work/cache-alone" --gradescope "$work/alone.json" \
  > "$work/alone.txt" 2>&1 || { cat "$work/alone.txt"; fail "carol's grading alone failed"; }
seconds() { sed -n 's/.*"execution_time" *: *\([0-9.]*\).*/\1/p' "$1" | head -1; }
alone=$(seconds "$work/alone.json")

bash "$repo/scripts/regrade" "$work/in" "$work/out" --jobs 2 --memory 2048 -- --problem 1b --cache "$work/cache" \
  2> "$work/regrade.err" || { cat "$work/regrade.err"; fail "the regrade failed"; }
cat "$work/regrade.err"
grep -q '1024 MiB of memory each' "$work/regrade.err" || fail "the regrade did not give each grading 1024 MiB"
grep -q '^Total: 20 / 20' "$work/out/carol/report.txt" || { cat "$work/out/carol/report.txt"; fail "carol lost points beside dave"; }
grep -q '^Total: 0 / 20' "$work/out/dave/report.txt" || fail "dave's 1b earned points"
if "$grader" --check-sandbox | grep -q '^memory budget: a group per grading'; then
  grep -q "compiling exercises/p1b.cpp took more than this grading's memory budget of 1024 MiB" "$work/out/dave/report.txt" ||
    { cat "$work/out/dave/report.txt"; fail "dave's report does not name his memory budget"; }
else
  echo "no writable memory cgroup here: dave's compile stops at its address-space limit instead"
fi
together=$(seconds "$work/out/carol/results.json")
[ -n "$alone" ] && [ -n "$together" ] || fail "no execution_time in carol's results.json"
echo "carol: ${alone} s alone, ${together} s beside dave (load $(cut -d' ' -f1 /proc/loadavg))"
echo "dave's compile failed alone at his budget; carol's grading was unchanged"
