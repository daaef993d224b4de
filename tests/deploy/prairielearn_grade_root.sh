#!/usr/bin/env bash
# PrairieLearn's external grader as PrairieLearn runs it, short of its container (this machine
# has no Docker engine): each submission graded by the entrypoint in a private mount namespace
# (unshare -m) whose /grade is a fresh temporary folder bind-mounted there, so that the
# entrypoint reads /grade/student and writes /grade/results/results.json, its own defaults (no
# OPSPACE_PL_ROOT; no OPSPACE_PL_GRADER either when GRADER is the release build's, the path the
# entrypoint takes by itself). Problem 1b's question:
#   the untouched stub -> 0; the reference -> 1, timed (PrairieLearn's default timeout is 30 s,
#   info.json's 60 s); a known mistake (the 1b mutant) -> between, its plots as images[], drawn
#   without a word from fontconfig; a file that does not compile -> 0, the compiler's error in the message;
#   no file -> not gradable; tests/tamper/cases/detached.cpp, a detached grandchild that rewrites
#   /grade/results/results.json for 8 s after the grader has written it -> 0, and 9 s later
#   results.json is the grader's still and the grandchild's marker was never written.
# The host's /grade (made empty as the mount point when missing, removed again) is empty after
# each: the bind mount stayed in its namespace. Where unshare -m is not allowed (not root, a
# container without CAP_SYS_ADMIN), it exits 77, ctest's SKIP_RETURN_CODE, saying why.
# Seen to fail: with --no-isolation among the grader options (the bundle's grader-options; the grader
# refuses it as root, the stub's results.json is not gradable); the mistake's case, before the
# entrypoint's key check was a loop (printf | grep -q under pipefail refused problem 1b as
# unknown, at random). Seen skipped by ctest with an unshare that fails.
#   bash tests/deploy/prairielearn_grade_root.sh REPO WORK GRADER
set -euo pipefail
repo=$1 work=$2 grader=$3
# shellcheck source=/dev/null
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
# shellcheck source=/dev/null
source "$(dirname "${BASH_SOURCE[0]}")/prairielearn_check.sh"

if [ "$(id -u)" -ne 0 ]; then
  echo "SKIPPED: not root: a private mount namespace with /grade bind-mounted needs root (unshare -m)"
  exit 77
fi
if ! unshare -m --propagation private true 2> /dev/null; then
  echo "SKIPPED: unshare -m is refused here (no CAP_SYS_ADMIN?): /grade cannot be bind-mounted privately"
  exit 77
fi
fresh_work "$work"

# One run at a time on this machine: the mount point /grade is shared by every clone's test.
exec 9> /tmp/opspace-prairielearn-grade.lock
flock 9
made_grade=0
if [ ! -e /grade ]; then
  mkdir /grade
  made_grade=1
fi
[ -d /grade ] && [ -z "$(ls -A /grade)" ] || fail "/grade exists and is not an empty folder: it is not this test's to use"
cleanup() { [ "$made_grade" = 0 ] || rmdir /grade 2> /dev/null || true; }
trap cleanup EXIT

entrypoint="$repo/deploy/prairielearn/entrypoint.sh"
grader_env=()
[ "$grader" -ef "$repo/build/release/apps/hw2-grade" ] || grader_env=("OPSPACE_PL_GRADER=$grader")

# grade NAME FILE...: a fresh folder with FILEs in student/ (a FILE a:b is a copied as b), the
# entrypoint run with it as /grade; its results.json kept as WORK/NAME.json, its time printed.
grade() {
  local name=$1 root="$work/$1" f
  shift
  mkdir -p "$root/student"
  for f in "$@"; do cp "${f%%:*}" "$root/student/${f##*:}"; done
  local t0=$SECONDS
  # The bind mount and everything below it live in the new namespace only.
  env -u OPSPACE_PL_ROOT -u OPSPACE_PL_GRADER "${grader_env[@]}" \
    unshare -m --propagation private bash -c 'mount --bind "$1" /grade && exec bash "$2" "$3"' _ "$root" "$entrypoint" "$key" \
    > "$work/$name.log" 2>&1 || { cat "$work/$name.log"; fail "the entrypoint exited non-zero ($name)"; }
  echo "TIME entrypoint in a private /grade ($name): $((SECONDS - t0)) s (load: $(cut -d' ' -f1-3 /proc/loadavg))"
  [ -z "$(ls -A /grade)" ] || fail "$name: the host's /grade is not empty: the bind mount left its namespace"
  cp "$root/results/results.json" "$work/$name.json"
}


stub="$work/stub-p$key.cpp"
git -C "$repo" show "HEAD:exercises/p$key.cpp" > "$stub"
grade stub "$stub:p$key.cpp"
check stub -DSCORE=0 -DPOINTS="$points"

start=$SECONDS
grade reference "$repo/solutions/p$key.cpp:p$key.cpp"
check reference -DSCORE=1 -DPOINTS="$points"
# PrairieLearn's default timeout per question; info.json asks 60 s, the entrypoint stops at 50.
[ $((SECONDS - start)) -le 30 ] || echo "NOTE: problem $key's reference took more than PrairieLearn's default 30 s here"

# A known mistake: its failed simulated tests' pictures (cairo's, in the grader) as images[].
grade mistake "$repo/tests/mutants/p1b_part3_pinv.cpp:p$key.cpp"
check mistake -DPOINTS="$points" -DIMAGES=ON -DSCORE=BETWEEN
! grep -i fontconfig "$work/mistake.log" || fail "mistake: fontconfig complained while the pictures were drawn"

printf 'this is not C++\n' > "$work/broken.cpp"
grade broken "$work/broken.cpp:p$key.cpp"
check broken -DSCORE=0 -DPOINTS="$points" "-DMESSAGE=p$key\\.cpp:1:"

grade missing
check missing "-DFORMAT_ERROR=p$key\\.cpp is missing"

# The tamper suite's detached grandchild, aimed at PrairieLearn's results file.
sed -e "s|@RESULTS_JSON@|/grade/results/results.json|g" -e "s|@WORK@|$work|g" -e "s|@TOTAL@|$OPSPACE_TOTAL|g" \
  "$repo/tests/tamper/cases/detached.cpp" > "$work/detached.cpp"
grade detached "$work/detached.cpp:p$key.cpp"
written=$(sha256sum < "$work/detached/results/results.json")
sleep 9  # the grandchild's 8 tries, one a second, and one more
[ "$(sha256sum < "$work/detached/results/results.json")" = "$written" ] ||
  fail "detached: results.json changed after the entrypoint ended: $(head -c 300 "$work/detached/results/results.json")"
[ ! -e "$work/pwned" ] || fail "detached: the grandchild outlived the grading (it wrote $work/pwned)"
check detached -DSCORE=0 -DPOINTS="$points"
echo "in a private mount namespace with /grade bind-mounted, the entrypoint grades the stub 0, the reference 1, a mistake with its pictures, a broken file 0, refuses a missing file, and a detached grandchild cannot rewrite its results"
