#!/usr/bin/env bash
# An exercise is compiled with the precompiled <Eigen/Dense> (grader/CMakeLists.txt: with GCC, a
# copy of the library's own), not by parsing Eigen again: GCC loads a precompiled header only
# when the flags it was built with agree with the compile's (the macros, -O, the language, the
# sanitizers), and otherwise parses the header silently, so only a slower grade would show it.
# Each stub is compiled with the runner toolchain's compile= flags: -H names the header GCC used,
# `! <path>.gch` when it is the precompiled one; -Winvalid-pch says why one was refused. Seen to
# fail with the copy's flags changed (a -DEIGEN_NO_DEBUG the exercises lack, -O0).
#   bash check_exercise_pch.sh TOOLCHAIN_TXT SOURCE_DIR WORK
set -euo pipefail
toolchain=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAILED: $*"; exit 1; }

compile=()
while IFS= read -r line; do
  case "$line" in compile=*) compile+=("${line#compile=}") ;; esac
done < "$toolchain"
[ "${#compile[@]}" -gt 0 ] || fail "$toolchain has no compile= line"
pch=""
for ((i = 0; i + 1 < ${#compile[@]}; i++)); do
  [ "${compile[$i]}" = -include ] && pch=${compile[$((i + 1))]}
done
[ -n "$pch" ] || fail "the toolchain includes no precompiled header (-include)"
[ -f "$pch.gch" ] || fail "$pch.gch does not exist"

checked=0
for stub in "$source"/exercises/p*.cpp; do
  name=$(basename "$stub" .cpp)
  "${compile[@]}" -Winvalid-pch -H -fsyntax-only "$stub" > "$work/$name.txt" 2>&1 ||
    { cat "$work/$name.txt"; fail "$name.cpp does not compile with the toolchain's flags"; }
  grep -qxF "! $pch.gch" "$work/$name.txt" ||
    { head -20 "$work/$name.txt"; fail "$name.cpp was compiled without the precompiled $pch.gch"; }
  checked=$((checked + 1))
done
[ "$checked" -ge 5 ] || fail "only $checked exercises found in $source/exercises"
echo "every exercise ($checked) compiled with the precompiled $(basename "$pch")"
