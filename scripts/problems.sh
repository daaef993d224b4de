# The list of problems (problems.txt, at the top of the repository) for the shell: sourced by
# scripts/regrade, deploy/collect_submission.sh and tests/deploy/*.sh. Sets
#   OPSPACE_KEYS     the keys, in the list's order (1a 1b ...)
#   OPSPACE_POINTS   each key's points, in the same order
#   OPSPACE_TOTAL    their sum
#   OPSPACE_PROBLEMS the problems' folders' parent (problems/), absolute
# grader/problems.cmake reads the same list for CMake, and checks its lines.
OPSPACE_KEYS=() OPSPACE_POINTS=() OPSPACE_TOTAL=0
while read -r opspace_key opspace_points _; do
  case "$opspace_key" in '' | '#'*) continue ;; esac
  OPSPACE_KEYS+=("$opspace_key")
  OPSPACE_POINTS+=("$opspace_points")
  OPSPACE_TOTAL=$((OPSPACE_TOTAL + opspace_points))
done < "$(dirname "${BASH_SOURCE[0]}")/../problems.txt"
unset opspace_key opspace_points
OPSPACE_PROBLEMS="$(cd "$(dirname "${BASH_SOURCE[0]}")/../problems" && pwd)"

# opspace_points KEY: problem KEY's points on stdout; exit status 1 if the list has no KEY.
opspace_points() {
  local i
  for i in "${!OPSPACE_KEYS[@]}"; do
    [ "${OPSPACE_KEYS[$i]}" != "$1" ] || { echo "${OPSPACE_POINTS[$i]}"; return 0; }
  done
  return 1
}

# opspace_stubs_untouched DIR: whether DIR holds each problem's exercise file exactly as shipped
# (its SHA-256 in problems/<key>/stub.sha256). Exit status 0 if so.
opspace_stubs_untouched() {
  local key
  for key in "${OPSPACE_KEYS[@]}"; do
    (cd "$1" && sha256sum --quiet -c "$OPSPACE_PROBLEMS/$key/stub.sha256") > /dev/null 2>&1 || return 1
  done
}
