#!/usr/bin/env bash
# One rule keeps a problem's secret side out of the handout: whatever a problem's grade/ folder
# holds (a new graded test, a helper header, a note, a nested folder, an odd name) is left out,
# and nothing beside it is. Feeds scripts/handout --filter the repository's files plus planted
# ones for every problem of problems.txt, as `git ls-files` would list them once committed.
#   bash tests/deploy/handout_secret_side.sh REPO
set -euo pipefail
repo=$1
fail() { echo "FAIL: $*"; exit 1; }
source "$repo/scripts/problems.sh"
planted=() public=()
for key in "${OPSPACE_KEYS[@]}"; do
  planted+=("problems/$key/grade/planted_secret.cpp" "problems/$key/grade/helpers/planted.hpp"
            "problems/$key/grade/a note with spaces.md")
  # Beside the secret side: public files, and names that only look like it.
  public+=("problems/$key/contract.hpp" "problems/$key/guide.md" "problems/$key/run/grade.hpp"
           "problems/$key/grade_table.md")
done
kept=$( { (cd "$repo" && git ls-files); printf '%s\n' "${planted[@]}" "${public[@]}"; } | bash "$repo/scripts/handout" --filter)
for path in "${planted[@]}"; do
  ! grep -qxF "$path" <<< "$kept" || fail "the handout would ship $path, a file of a problem's grade/"
done
if leaked=$(grep -E '^problems/[^/]+/grade/' <<< "$kept"); then
  fail "the handout would ship files of a problem's grade/: $leaked"
fi
for path in "${public[@]}"; do
  grep -qxF "$path" <<< "$kept" || fail "the handout would leave out $path, which is not a problem's secret side"
done
# The repository's own secret sides exist (the rule has something to do) and are left out.
secrets=$(cd "$repo" && git ls-files 'problems/*/grade/*' | wc -l)
[ "$secrets" -gt 0 ] || fail "no file of the repository is under problems/*/grade/: the check proves nothing"
echo "the handout leaves out ${#planted[@]} planted files and the repository's $secrets under problems/*/grade/, and keeps ${#public[@]} beside them"
