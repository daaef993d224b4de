#!/usr/bin/env bash
# PrairieLearn's external grader runs this in the image (Dockerfile beside it), as root, once per
# submission: info.json's externalGradingOptions.entrypoint,
#   /autograder/source/opspace/deploy/prairielearn/entrypoint.sh [KEY]
# (PrairieLearn splits the entrypoint at spaces: KEY is the problem the question grades, its
# file p<KEY>.cpp; without KEY the question takes every problem's file). It reads the student's
# files from $GRADE/student, grades them with the trusted grader and always writes
# $GRADE/results/results.json (PrairieLearn's format, docs/instructor.md):
#   - a file missing, misnamed or not a regular file: gradable false, format_errors naming it
#     (PrairieLearn then counts no attempt);
#   - otherwise the grader's own (hw2-grade --prairielearn): score in [0, 1], tests[], images;
#   - a grader that cannot run or takes longer than OPSPACE_GRADE_LIMIT seconds: gradable false,
#     saying so (the student is not at fault and loses no attempt).
# GRADE is /grade, or OPSPACE_PL_ROOT (tests/deploy/prairielearn.sh: a temporary folder);
# OPSPACE_PL_GRADER replaces the image's grader (the tests': this build's).
set -uo pipefail

GRADE=${OPSPACE_PL_ROOT:-/grade}
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
GRADER=${OPSPACE_PL_GRADER:-$REPO/build/release/apps/hw2-grade}
RESULTS_DIR="$GRADE/results"
RESULTS="$RESULTS_DIR/results.json"
# Below info.json's timeout (60 s), so that a submission that hangs still gets its results.json
# instead of PrairieLearn's bare "timed out": 10 s for the kill and the writing.
LIMIT=${OPSPACE_GRADE_LIMIT:-50}

mkdir -p "$RESULTS_DIR"
rm -f "$RESULTS"
# shellcheck source=/dev/null
source "$REPO/scripts/problems.sh"
keys=("${OPSPACE_KEYS[@]}")
[ $# -eq 0 ] || keys=("$1")

# A JSON string of printable ASCII text (every text below is, names cleaned by shown()).
json_string() {
  local s=${1//\\/\\\\}
  printf '"%s"' "${s//\"/\\\"}"
}
# A file's name as the student sees it: printable ASCII only, at most 120 characters.
shown() { printf '%s' "$1" | LC_ALL=C tr -c '[:print:]' '?' | cut -c1-120; }
# not_gradable TEXT...: results.json with gradable false, one format error per argument.
not_gradable() {
  local list="" e
  for e in "$@"; do list+="${list:+, }$(json_string "$e")"; done
  printf '{"gradable": false, "format_errors": [%s], "message": %s, "tests": []}\n' "$list" \
    "$(json_string "This submission was not graded and counts no attempt: $1")" > "$RESULTS"
  printf 'entrypoint.sh: not gradable: %s\n' "$*" >&2
}

# A loop, not `printf | grep -q`: grep -q leaves at its match, and under pipefail printf's next
# line then fails the pipe (SIGPIPE): 45 of 3000 tries here refused problem 1b.
named=0
for key in "${OPSPACE_KEYS[@]}"; do [ "$#" -eq 0 ] || [ "$key" != "$1" ] || named=1; done
if [ $# -gt 0 ] && [ "$named" = 0 ]; then
  not_gradable "this question names no problem '$(shown "$1")' (problems.txt): tell your instructor"
  exit 0
fi

# --- the student's files: each one the question grades, a regular file under its own name ---
work=$(mktemp -d /tmp/opspace-pl-XXXXXX) || { not_gradable "the autograder cannot create a folder in /tmp: tell your instructor"; exit 0; }
trap 'rm -rf "$work"' EXIT
chmod 700 "$work"
mkdir -p "$work/exercises"
others=()
if [ -d "$GRADE/student" ]; then
  while IFS= read -r -d '' path; do others+=("$(shown "${path#"$GRADE/student/"}")"); done \
    < <(find "$GRADE/student" -mindepth 1 -maxdepth 2 \( -type f -o -type l \) -print0 2> /dev/null | head -z -n 20)
fi
errors=()
for key in "${keys[@]}"; do
  name="p$key.cpp" file="$GRADE/student/p$key.cpp"
  if [ -L "$file" ]; then
    errors+=("$name is a symbolic link: submit the file itself")
  elif [ ! -f "$file" ]; then
    seen=""
    if [ ${#others[@]} -gt 0 ]; then
      seen=$(printf '%s, ' "${others[@]}")
      seen=" (the submission holds: ${seen%, })"
    fi
    errors+=("$name is missing: this question grades a file named exactly $name$seen")
  elif [ "$(stat -c %s "$file")" -gt $((1024 * 1024)) ]; then
    errors+=("$name is larger than 1 MiB: the grader reads no file that large")
  else
    cp "$file" "$work/exercises/$name"
  fi
done
if [ ${#errors[@]} -gt 0 ]; then
  not_gradable "${errors[@]}"
  exit 0
fi
# The problems the question does not grade are the untouched stubs (hw2-grade reads the folder).
for key in "${OPSPACE_KEYS[@]}"; do
  [ -e "$work/exercises/p$key.cpp" ] || cp "$REPO/exercises/p$key.cpp" "$work/exercises/"
done

# --- grading ---------------------------------------------------------------------------------
# The instructor's grader options (scripts/autograder DIR -- OPTIONS...), one per line, as the
# Gradescope bundle reads them.
options=()
[ -f "$REPO/deploy/grader-options" ] && mapfile -t options < "$REPO/deploy/grader-options"
[ ${#keys[@]} -eq 1 ] && options+=(--problem "${keys[0]}")
reason=""
if [ ! -x "$GRADER" ]; then
  reason="the grader $GRADER is missing"
else
  timeout --kill-after=5 "$LIMIT" "$GRADER" --exercises "$work/exercises" --prairielearn "$RESULTS" "${options[@]}"
  code=$?
  if [ "$code" -eq 124 ] || [ "$code" -eq 137 ]; then
    # The submission's doing (each test has its own limit, --timeout): graded, 0.
    printf '{"gradable": true, "score": 0, "message": %s, "tests": []}\n' \
      "$(json_string "Grading took more than $LIMIT s and was stopped: does your code loop or wait forever?")" > "$RESULTS"
    exit 0
  elif [ "$code" -eq 3 ]; then
    reason="the grader's sandbox cannot be built in this container, so it refused to run the submission (docs/grader.md, --unprotected)"
  elif [ "$code" -ne 0 ]; then
    reason="the grader exited with code $code"
  elif [ ! -s "$RESULTS" ]; then
    reason="the grader wrote no results"
  fi
fi
if [ -n "$reason" ]; then
  not_gradable "the autograder could not grade this submission: $reason. This is not your fault if your file is named as asked: tell your instructor."
fi
exit 0
