#!/usr/bin/env bash
# CMake 3.22, Ubuntu 22.04's (Gradescope's default image), is the oldest CMake the project
# builds with. Debian has no CMake 3.22 to build with, so this checks what can be checked
# without it (docs/instructor.md, "CMake 3.22"):
#   - every cmake_minimum_required says 3.22, and CMakePresets.json's cmakeMinimumRequired too;
#   - CMakePresets.json's format version is at most 3, the newest CMake 3.22 reads (3.21 added 3);
#   - none of the commands, keywords, generator expressions or command-line options that CMake's
#     documentation marks as added in 3.23 or later, among those a project like this one could
#     reach for, appears in the CMake files or the scripts that call cmake and ctest.
#   bash tests/scripts/check_cmake_minimum.sh REPO
set -euo pipefail
repo=$1
minimum=3.22
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

mapfile -t cmake_files < <(find "$repo" -path "$repo/build" -prune -o -path '*/node_modules' -prune -o \
                           \( -name CMakeLists.txt -o -name '*.cmake' \) -type f -print | LC_ALL=C sort)
mapfile -t script_files < <(find "$repo/scripts" "$repo/deploy" "$repo/tests" "$repo/.ci" -type f \
                            \( -name '*.sh' -o -name run -o -name setup.sh -o -name run_autograder -o -perm -u+x \) \
                            -not -path '*/node_modules/*' 2> /dev/null | LC_ALL=C sort)
[ "${#cmake_files[@]}" -gt 0 ] || fail "no CMake file found under $repo"

# --- the declared minimum ------------------------------------------------------------------------
for f in "${cmake_files[@]}"; do
  while IFS= read -r line; do
    [[ "$line" == *"VERSION $minimum)"* ]] || fail "${f#"$repo"/}: '$line' (the minimum is $minimum)"
  done < <(grep -h 'cmake_minimum_required' "$f" | grep -v '^ *#' || true)
done
top_minimum=$(grep -c "^cmake_minimum_required(VERSION $minimum)" "$repo/CMakeLists.txt" || true)
[ "$top_minimum" = 1 ] || fail "CMakeLists.txt does not open with cmake_minimum_required(VERSION $minimum)"

presets=$repo/CMakePresets.json
version=$(sed -n 's/^ *"version": *\([0-9]*\),*$/\1/p' "$presets" | head -1)
if ! [[ "$version" =~ ^[0-9]+$ ]] || [ "$version" -gt 3 ]; then
  fail "CMakePresets.json's version is '${version}': CMake 3.22 reads versions 1 to 3"
fi
required=$(tr -d ' \n' < "$presets" | sed -n 's/.*"cmakeMinimumRequired":{"major":\([0-9]*\),"minor":\([0-9]*\),"patch":\([0-9]*\)}.*/\1.\2.\3/p')
[ "$required" = "$minimum.0" ] || fail "CMakePresets.json's cmakeMinimumRequired is '$required', not $minimum.0"

# --- features newer than 3.22 ---------------------------------------------------------------------
# Each from the "versionadded" notes of CMake's own documentation (3.23 to 3.27), as fixed strings.
newer_in_cmake=(
  'block('                 # 3.25
  'endblock('              # 3.25
  ' PATH_EQUAL '           # if(), 3.24
  '$<PATH:'                # 3.24
  '$<PATH_EQUAL:'          # 3.24
  '$<LINK_LIBRARY:'        # 3.24
  '$<LINK_GROUP:'          # 3.24
  '$<LIST:'                # 3.27
  'FILE_SET'               # target_sources(), 3.23
  ' PROPAGATE'             # return(), 3.25
  'GET_MESSAGE_LOG_LEVEL'  # cmake_language(), 3.25
  'CMAKE_PROJECT_TOP_LEVEL_INCLUDES'  # 3.24
  'COMPILE_WARNING_AS_ERROR'          # 3.24
  'CMAKE_FIND_PACKAGE_TARGETS_GLOBAL' # 3.24
  'BYPASS_PROVIDER'        # find_package(), 3.24
  'REGISTRY_VIEW'          # 3.24
  'RANGE_START'            # file(DOWNLOAD), 3.24
  'cmake_language(SET_DEPENDENCY_PROVIDER'  # 3.24
)
newer_on_command_line=(
  '--fresh'                        # cmake, 3.24
  '--compile-no-warning-as-error'  # cmake, 3.24
  'env --modify'                   # cmake -E env, 3.25
  '--test-output-truncation'       # ctest, 3.24
  'copy_directory_if_different'    # cmake -E, 3.26
  '--touch'                        # cmake -E tar, 3.24
)
# One grep per file, listing the words it found (fixed strings); grep's exit 1 is "none", 2 an
# error, which fails the check rather than passing it.
cmake_words=() command_words=()
for word in "${newer_in_cmake[@]}" "${newer_on_command_line[@]}"; do cmake_words+=(-e "$word"); done
for word in "${newer_on_command_line[@]}"; do command_words+=(-e "$word"); done
found() {  # found FILE KIND GREP-ARGS...: prints the words of the lists that FILE's lines hold
  local f=$1 kind=$2 lines status=0
  shift 2
  if [ "$kind" = cmake ]; then lines=$(grep -v '^ *#' "$f" || true)
  else lines=$(grep -E '\b(cmake|ctest)\b' "$f" | grep -v '^ *#' || true); fi
  printf '%s\n' "$lines" | grep -oF "$@" | sort -u || status=${PIPESTATUS[1]}
  [ "$status" -le 1 ] || echo "grep-error:$status"
}
for f in "${cmake_files[@]}"; do
  while IFS= read -r word; do
    case "$word" in
      "") ;;
      grep-error:*) fail "grep could not search ${f#"$repo"/} (exit ${word#grep-error:})" ;;
      *) fail "${f#"$repo"/} uses '$word', newer than CMake $minimum" ;;
    esac
  done < <(found "$f" cmake "${cmake_words[@]}")
done
self=$(realpath "${BASH_SOURCE[0]}")
for f in "${script_files[@]}"; do
  [ "$(realpath "$f")" = "$self" ] && continue
  while IFS= read -r word; do
    case "$word" in
      "") ;;
      grep-error:*) fail "grep could not search ${f#"$repo"/} (exit ${word#grep-error:})" ;;
      *) fail "${f#"$repo"/} calls cmake or ctest with '$word', newer than CMake $minimum" ;;
    esac
  done < <(found "$f" script "${command_words[@]}")
done

echo "${#cmake_files[@]} CMake files and ${#script_files[@]} scripts checked against CMake $minimum; presets version $version"
[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "all passed"
