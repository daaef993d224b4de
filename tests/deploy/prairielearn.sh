#!/usr/bin/env bash
# PrairieLearn's external grader, as it runs a question of problem 1b, without Docker (there is no
# engine here; the image's recipe, deploy/prairielearn/Dockerfile, is not built by any test): the
# entrypoint grades a fresh GRADE root (OPSPACE_PL_ROOT, PrairieLearn's /grade) whose student
# folder holds p1b.cpp, with this build's grader, and each results.json is checked as PrairieLearn
# reads it (check_prairielearn.cmake: its fields, its size):
#   the reference -> 1; the untouched stub -> 0; a known mistake (the 1b mutant) -> between,
#   with its failed runs' plots as images; a file that does not compile -> 0, the compiler's
#   error in the message; the file missing, misnamed (P1B.cpp) or a symbolic
#   link -> not gradable, the format error naming p1b.cpp.
# Problem 1b alone: a question grades one problem, and 1b has simulated tests (the pictures) yet
# grades in seconds.
#   bash tests/deploy/prairielearn.sh REPO WORK GRADER
set -euo pipefail
repo=$1 work=$2 grader=$3
# shellcheck source=/dev/null
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
# shellcheck source=/dev/null
source "$(dirname "${BASH_SOURCE[0]}")/prairielearn_check.sh"
fresh_work "$work"

# grade NAME FILE...: a fresh GRADE root with FILEs in student/ (a FILE a:b is a copied as b),
# graded by the entrypoint; its results.json kept as WORK/NAME.json.
grade() {
  local name=$1 root="$work/$1" f
  shift
  mkdir -p "$root/student"
  for f in "$@"; do cp "${f%%:*}" "$root/student/${f##*:}"; done
  local t0
  t0=$(date +%s)
  OPSPACE_PL_ROOT="$root" OPSPACE_PL_GRADER="$grader" bash "$repo/deploy/prairielearn/entrypoint.sh" "$key" \
    > "$work/$name.log" 2>&1 || { cat "$work/$name.log"; fail "the entrypoint exited non-zero ($name)"; }
  echo "TIME entrypoint ($name): $(( $(date +%s) - t0 )) s"
  cp "$root/results/results.json" "$work/$name.json"
}


grade reference "$repo/solutions/p$key.cpp:p$key.cpp"
check reference -DSCORE=1 -DPOINTS="$points"

stub="$work/stub-p$key.cpp"
git -C "$repo" show "HEAD:exercises/p$key.cpp" > "$stub"
grade stub "$stub:p$key.cpp"
check stub -DSCORE=0 -DPOINTS="$points"

grade mistake "$repo/tests/mutants/p1b_part3_pinv.cpp:p$key.cpp"
check mistake -DPOINTS="$points" -DIMAGES=ON -DSCORE=BETWEEN

printf 'this is not C++\n' > "$work/broken.cpp"
grade broken "$work/broken.cpp:p$key.cpp"
check broken -DSCORE=0 -DPOINTS="$points" "-DMESSAGE=p$key\\.cpp:1:"

grade missing
check missing "-DFORMAT_ERROR=p$key\\.cpp is missing"
grade misnamed "$repo/solutions/p$key.cpp:P1B.cpp"
check misnamed "-DFORMAT_ERROR=p$key\\.cpp is missing.*holds: P1B\\.cpp"
mkdir -p "$work/link/student"
ln -s "$repo/solutions/p$key.cpp" "$work/link/student/p$key.cpp"
grade link
check link "-DFORMAT_ERROR=p$key\\.cpp is a symbolic link"
echo "the PrairieLearn entrypoint grades the reference 1, the stub 0, a mistake with its plots, a broken file 0, and refuses a missing, misnamed or linked file"
