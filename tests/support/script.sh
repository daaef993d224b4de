# What the test scripts of tests/deploy/, tests/graded/ and tests/tamper/ share, sourced first:
#   source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
# It sources scripts/problems.sh (the list of problems: OPSPACE_KEYS, OPSPACE_POINTS,
# OPSPACE_TOTAL) and defines
#   fail MESSAGE...           "FAIL: MESSAGE" on stderr, then exit 1
#   fresh_work DIR [SUB...]   DIR emptied and made again, with the folders SUB below it
#   skip_unless_stubs_untouched
#                             exit 0, "SKIPPED: ..." (the tests' SKIP_REGULAR_EXPRESSION), when
#                             this repository's exercises/ are not the shipped stubs: the script
#                             grades a student's missing file as the stub, which then differs

source "$(dirname "${BASH_SOURCE[0]}")/../../scripts/problems.sh"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

fresh_work() {
  local dir=$1
  shift
  rm -rf "$dir"
  mkdir -p "$dir"
  local sub
  for sub in "$@"; do mkdir -p "$dir/$sub"; done
}

skip_unless_stubs_untouched() {
  if ! opspace_stubs_untouched "$OPSPACE_PROBLEMS/../exercises"; then
    echo "SKIPPED: exercises/ have been edited (scripts/regrade grades a missing file as the shipped stub)"
    exit 0
  fi
}
