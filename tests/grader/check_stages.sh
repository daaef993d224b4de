#!/usr/bin/env bash
# The grader's includes run one way (grader/README.md, "Its stages"): every #include of a C++
# file under grader/ is read, each file mapped to its stage by its folder, and the check fails
#   - on an include of a higher stage (a lower stage never includes a higher one);
#   - on a loop between units (a unit: a folder's name.hpp with its name.cpp), two-way ties
#     included, at any stage;
#   - on an include between the runner's side (untrusted/) and the grader's (trusted/, suite/);
#   - on a folder of grader/trusted/ that is no stage, or a file of grader/ over 400 lines.
# Each failure names the file, its line and the include.
#   bash tests/grader/check_stages.sh REPO
set -euo pipefail
repo=${1:?usage: check_stages.sh REPO}
cd "$repo/grader"

# The stages, lowest first: a file may include its own stage's and the lower ones'. protocol/ is
# the floor both sides share; suite/ (the graded tests' shared shapes) stands on the judge; the
# files at the top of trusted/ are the pipeline (grader.cpp) and its command line.
stages=(protocol common sandbox build run judge suite report class pipeline)
max_lines=400

stage_of() {  # the stage of a path under grader/, or "" when it is no file of grader/
  case $1 in
    protocol/*) echo protocol ;;
    untrusted/*) echo untrusted ;;
    suite/*) echo suite ;;
    trusted/*/*) local rest=${1#trusted/}; echo "${rest%%/*}" ;;
    trusted/*) echo pipeline ;;
    *) echo "" ;;
  esac
}
rank_of() {
  local i
  for i in "${!stages[@]}"; do [ "${stages[$i]}" = "$1" ] && { echo "$i"; return; }; done
  echo -1
}

failures=0
say() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

for dir in trusted/*/; do
  dir=${dir%/}
  [ "$(rank_of "${dir#trusted/}")" -ge 0 ] || say "grader/$dir is no stage of tests/grader/check_stages.sh (place it in the order)"
done

# Each include as "file line target": the included file found as the compiler finds it (beside
# the file, then from grader/trusted/, grader/, grader/suite/ and the repository's top); includes
# of nothing under grader/ (the library, the problems, the system's) are left out.
edges=$(mktemp)
trap 'rm -f "$edges"' EXIT
while IFS= read -r file; do
  lines=$(wc -l < "$file")
  [ "$lines" -le "$max_lines" ] || say "grader/$file has $lines lines (at most $max_lines: split it by idea)"
  here=$(dirname "$file")
  { grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*["<][^">]+[">]' "$file" || true; } |
    sed -E 's/^([0-9]+):[^"<]*["<]([^">]+)[">].*/\1 \2/' |
    while read -r line target; do
      found=""
      for candidate in "$here/$target" "trusted/$target" "$target" "suite/$target" "../$target"; do
        if [ -f "$candidate" ]; then found=$(realpath -m --relative-to=. "$candidate"); break; fi
      done
      case $found in "" | ../*) continue ;; esac
      echo "$file $line $found"
    done >> "$edges"
done < <(find protocol untrusted trusted suite -name '*.[ch]pp' | sort)

# Upward includes, and the wall between the two sides.
while read -r file line target; do
  from=$(stage_of "$file") to=$(stage_of "$target")
  if [ "$from" = untrusted ] || [ "$to" = untrusted ]; then
    [ "$from" = "$to" ] || [ "$to" = protocol ] ||
      say "grader/$file:$line includes grader/$target across the wall between the runner and the grader"
    continue
  fi
  [ "$(rank_of "$to")" -le "$(rank_of "$from")" ] ||
    say "grader/$file:$line includes grader/$target: stage $from includes the higher stage $to"
done < "$edges"

# Loops between units: a depth-first search of the units' graph; a unit met again on the path
# closes a loop, shown whole.
loops=$(awk '
  function unit(path) { sub(/\.[ch]pp$/, "", path); return path }
  {
    a = unit($1); b = unit($3)
    if (a == b || (a SUBSEP b) in seen) next
    seen[a, b] = 1; next_of[a] = next_of[a] " " b; where[a, b] = $1 ":" $2 " includes " $3
    units[a] = 1; units[b] = 1
  }
  function visit(u, path,    n, list, i, v, k, loop) {
    state[u] = 1; path = path " " u
    n = split(next_of[u], list, " ")
    for (i = 1; i <= n; ++i) {
      v = list[i]
      if (state[v] == 1) {
        loop = ""; k = split(path, seq, " ")
        for (; k > 0 && seq[k] != v; --k) loop = seq[k] " -> " loop
        print "a loop between units: " v " -> " loop v " (" where[u, v] ")"
      } else if (state[v] == 0) visit(v, path)
    }
    state[u] = 2
  }
  END { for (u in units) if (state[u] == 0) visit(u, "") }
' "$edges")
if [ -n "$loops" ]; then
  while IFS= read -r loop; do say "$loop"; done <<< "$loops"
fi

count=$(wc -l < "$edges")
[ "$count" -gt 0 ] || say "no include of grader/ was read: is $repo the repository?"
[ "$failures" -eq 0 ] || exit 1
echo "grader/: $count includes between its files, each to its own or a lower stage, no loop; no file over $max_lines lines"
