#!/usr/bin/env bash
# One rule keeps the secret side out of the handout and out of the autograder's image: every
# grade/ folder of problems/ and grader/ (scripts/secret_side.sh), whatever it holds (a new
# graded test, a helper header, a note, a nested folder, an odd name), is left out, and nothing
# beside it is. Feeds scripts/handout --filter the repository's files plus planted ones for every
# problem of problems.txt and for the suite, as `git ls-files` would list them once committed;
# then removes the secret side from a scratch tree of the same files as deploy/setup.sh does and
# checks that the two leave out the same files.
#   bash tests/deploy/handout_secret_side.sh REPO
set -euo pipefail
repo=$1
fail() { echo "FAIL: $*"; exit 1; }
source "$repo/scripts/problems.sh"
planted=("grader/suite/grade/planted_secret.cpp" "grader/suite/grade/helpers/planted.hpp"
         "grader/trusted/judge/grade/planted.hpp")
public=("grader/suite/grade.hpp" "grader/suite/grade_table.md" "grader/trusted/judge/grading.hpp")
for key in "${OPSPACE_KEYS[@]}"; do
  planted+=("problems/$key/grade/planted_secret.cpp" "problems/$key/grade/helpers/planted.hpp"
            "problems/$key/grade/a note with spaces.md")
  # Beside the secret side: public files, and names that only look like it.
  public+=("problems/$key/contract.hpp" "problems/$key/guide.md" "problems/$key/run/grade.hpp"
           "problems/$key/grade_table.md")
done
all=$( { (cd "$repo" && git ls-files); printf '%s\n' "${planted[@]}" "${public[@]}"; } | sort -u)
kept=$(bash "$repo/scripts/handout" --filter <<< "$all")
for path in "${planted[@]}"; do
  ! grep -qxF "$path" <<< "$kept" || fail "the handout would ship $path, a file of a grade/ folder"
done
if leaked=$(grep -E '^(problems|grader)/(.*/)?grade/' <<< "$kept"); then
  fail "the handout would ship files of a grade/ folder: $leaked"
fi
for path in "${public[@]}"; do
  grep -qxF "$path" <<< "$kept" || fail "the handout would leave out $path, which is not on the secret side"
done
# The repository's own secret sides exist (the rule has something to do) and are left out.
secrets=$(cd "$repo" && git ls-files 'problems/*/grade/*' 'grader/suite/grade/*' | wc -l)
[ "$secrets" -gt 0 ] || fail "no file of the repository is in a grade/ folder: the check proves nothing"
[ -n "$(cd "$repo" && git ls-files 'grader/suite/grade/*')" ] || fail "grader/suite/grade/ holds no file: the suite's secret side moved?"

# deploy/setup.sh's removal, on a scratch tree of the same files: what remains of problems/ and
# grader/ is what the handout keeps of them.
grep -q '^opspace_remove_secret_side "\$REPO"$' "$repo/deploy/setup.sh" ||
  fail "deploy/setup.sh does not remove the secret side by scripts/secret_side.sh's rule"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
while IFS= read -r path; do
  case $path in problems/* | grader/*) mkdir -p "$work/$(dirname "$path")" && : > "$work/$path" ;; esac
done <<< "$all"
source "$repo/scripts/secret_side.sh"
opspace_remove_secret_side "$work"
[ -z "$(opspace_secret_folders "$work")" ] || fail "a grade/ folder is left after the removal"
left=$(cd "$work" && find problems grader -type f | sort)
handout_kept=$(grep -E '^(problems|grader)/' <<< "$kept" | sort)
if ! diff <(echo "$left") <(echo "$handout_kept") > "$work/difference"; then
  fail "deploy/setup.sh and scripts/handout leave out different files: $(cat "$work/difference")"
fi
echo "the handout and the autograder's image leave out ${#planted[@]} planted files and the repository's $secrets in grade/ folders, and keep ${#public[@]} beside them"
