#!/usr/bin/env bash
# One include style per layer, everywhere (docs/architecture.md, "Where each file lives"): the
# library's headers by their path from lib/include in quotes, "opspace/algorithms/dynamics.hpp";
# a problem's headers by their path from the top in angle brackets, <problems/2/contract.hpp>,
# the form a student's exercise file uses for its contract. Read from the C++ files git tracks
# (or, outside a git checkout, every .cpp/.hpp/.in but build/), the scaffold's templates among
# them. The contract's former path, <opspace/hw2/p<key>.hpp>, is a student's slip the grader
# names (grader/trusted/build/compiler_messages.cpp): the tests that write it are exempt.
#
#   bash tests/docs/check_include_style.sh [ROOT]      (ROOT: the repository, by default this one)
set -euo pipefail

root=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
cd "$root"
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  mapfile -t files < <(git ls-files -- '*.cpp' '*.hpp' '*.h' '*.cpp.in' '*.hpp.in')
else
  mapfile -t files < <(find . -path ./build -prune -o -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.in' \) -print | sed 's|^\./||')
fi
[ ${#files[@]} -gt 0 ] || { echo "no C++ file found under $root"; exit 1; }

# FILE:LINE: TEXT of each include in the other style.
wrong=$(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]+(<opspace/|"problems/)' "${files[@]}" |
  grep -vE '<opspace/hw2/' || true)
if [ -n "$wrong" ]; then
  echo "$wrong"
  echo "$(printf '%s\n' "$wrong" | wc -l) include(s) in the other style: write the library's headers as \"opspace/...\" and a problem's as <problems/...>"
  exit 1
fi
echo "${#files[@]} files: the library's headers in quotes, the problems' in angle brackets"
