#!/usr/bin/env bash
# Where the sandbox cannot be built (here: every namespace refused, by deny_namespaces), the
# grader refuses to run others' code (exit 3, saying why and what --unprotected does) and grades
# nothing; with --unprotected it grades, and its report opens with UNPROTECTED; --check-sandbox
# says which. Where it can (this machine, as root or with user namespaces), nothing says
# UNPROTECTED. Without the refusal (the grader before issue 38) the first grading ran: exit 0.
#   bash check_unprotected.sh DENY_NAMESPACES GRADER WORK
set -euo pipefail
deny=$1 grader=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAILED: $*"; exit 1; }

"$grader" --check-sandbox > "$work/check.txt" 2>&1 || { cat "$work/check.txt"; echo "SKIPPED: the sandbox is incomplete on this machine, so the contrast cannot be shown"; exit 0; }
grep -qx 'sandbox: complete' "$work/check.txt" || fail "--check-sandbox: $(cat "$work/check.txt")"
# How gradings share the CPU: a cgroup of the grading's own where the machine offers a writable
# one, else the runner's CPU time alone (docs/grader.md, "Between gradings").
grep -Eq '^cpu share: (a group per grading, cgroup v[12]|no writable cgroup here)' "$work/check.txt" ||
  fail "--check-sandbox does not say how the CPU is shared: $(cat "$work/check.txt")"
if [ "$(id -u)" -eq 0 ] && [ -w /sys/fs/cgroup/cpu/cgroup.procs ]; then
  grep -q '^cpu share: a group per grading, cgroup v1 cpu:' "$work/check.txt" || fail "a writable cgroup v1 cpu controller is not used"
fi

code=0
"$deny" "$grader" --check-sandbox > "$work/check-denied.txt" 2>&1 || code=$?
[ "$code" -eq 3 ] || fail "--check-sandbox without namespaces exited $code, expected 3: $(cat "$work/check-denied.txt")"
grep -q 'a PID namespace' "$work/check-denied.txt" || fail "--check-sandbox does not name the missing PID namespace"

code=0
"$deny" "$grader" --problem 1a --gradescope "$work/refused.json" > "$work/refused.txt" 2>&1 || code=$?
[ "$code" -eq 3 ] || { cat "$work/refused.txt"; fail "without namespaces the grader exited $code, expected 3 (refused)"; }
grep -q 'refused: the sandbox cannot be built here' "$work/refused.txt" || fail "the refusal does not say why"
grep -q -- '--unprotected' "$work/refused.txt" || fail "the refusal does not name --unprotected"
[ ! -e "$work/refused.json" ] || fail "a refused grading wrote results.json"
grep -q 'Total:' "$work/refused.txt" && fail "a refused grading graded"

"$deny" "$grader" --problem 1a --unprotected > "$work/unprotected.txt" 2>&1 || { cat "$work/unprotected.txt"; fail "--unprotected did not grade"; }
head -1 "$work/unprotected.txt" | grep -q '^UNPROTECTED: the sandbox is incomplete here (missing: [^)]*a PID namespace' ||
  { cat "$work/unprotected.txt"; fail "the unprotected report does not open with UNPROTECTED"; }
grep -q '^Total: ' "$work/unprotected.txt" || fail "the unprotected grading did not finish"

"$grader" --problem 1a > "$work/protected.txt" 2>&1 || fail "the grader failed where the sandbox holds"
grep -q 'UNPROTECTED' "$work/protected.txt" && fail "the report says UNPROTECTED where the sandbox holds"
echo "the grader refuses without its sandbox, and says UNPROTECTED when told to grade anyway"
