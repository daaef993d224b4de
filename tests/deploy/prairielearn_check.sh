# shellcheck shell=bash
# What the two PrairieLearn tests share (prairielearn.sh, prairielearn_grade_root.sh), sourced
# after tests/support/script.sh with $repo and $work set: the question's problem and its points,
# and the check of a results.json as PrairieLearn reads it (check_prairielearn.cmake).
# Problem 1b: a question grades one problem, and 1b has simulated tests (the pictures) yet
# grades in seconds.
checker="$repo/tests/deploy/check_prairielearn.cmake"
key=1b
points=$(opspace_points "$key") || fail "problems.txt has no problem $key"

# check NAME ARGS...: WORK/NAME.json checked (check_prairielearn.cmake ARGS); on a failure the
# entrypoint's own output too (WORK/NAME.log), which says what the grader did.
check() {
  local name=$1
  shift
  cmake -DJSON="$work/$name.json" "$@" -P "$checker" ||
    { tail -30 "$work/$name.log"; fail "$name: results.json is not what PrairieLearn should get"; }
}
