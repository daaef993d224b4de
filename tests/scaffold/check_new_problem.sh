#!/bin/bash
# check_new_problem.sh SOURCE WORK [KEY [ROBOT]]: a simulated problem is its folder, its line in
# problems.txt, its exercise and its solution (docs/grader.md, "Adding a problem"). In a copy of
# SOURCE (git's files as they are in the working tree, the uncommitted change with them) under
# WORK, scripts/new-problem makes problem KEY (default fe) on ROBOT (puma, the default, or iiwa); the copy is built, as the
# release preset, with the new problem's scenario and graded files compiled each alone (no unity
# unit lends them an include), only the targets grading needs; then
#   - its stub scores 0 and its solution full marks through hw2-grade;
#   - the graded suite's checks pass for it with nothing written by hand: its known mistake loses
#     exactly its tests, its rubric row says so, its case registered from problems.txt;
#   - its program runs, and says it has no live lab (--live);
#   - every path its comments cite exists;
#   - nothing changed in the copy outside problems/<KEY>/, problems.txt, exercises/p<KEY>.cpp and
#     solutions/p<KEY>.cpp.
# Set CMAKE_CXX_COMPILER_LAUNCHER=ccache (the build's objects are reused: CCACHE_BASEDIR is set to
# the copy, whose paths below it are SOURCE's).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
mkdir -p "$2"
source_dir=$(cd "$1" && pwd) work=$(cd "$2" && pwd) key=${3:-fe} robot=${4:-puma}
command -v git > /dev/null || { echo "SKIPPED: no git"; exit 0; }
git -C "$source_dir" rev-parse --git-dir > /dev/null 2>&1 || { echo "SKIPPED: $source_dir is no git checkout"; exit 0; }
start=$(date +%s)
seconds() { echo "$(( $(date +%s) - start )) s"; }

# The copy, as a repository of its own: its first commit is SOURCE's working tree.
copy=$work/tree
mkdir -p "$copy"
find "$copy" -mindepth 1 -maxdepth 1 ! -name build -exec rm -rf {} +  # its build stays: ninja's state
# (a tracked file the working tree deleted is passed over: --ignore-failed-read; tar keeps the
# files' times, so that the copy's build rebuilds only what the change and the problem touch)
(cd "$source_dir" && git ls-files -z --cached --others --exclude-standard |
   tar --null -T - --ignore-failed-read -cf - 2> /dev/null) | (cd "$copy" && tar -xf -)
git -C "$copy" init -q
git -C "$copy" add -A
git -C "$copy" -c user.name=scaffold -c user.email=scaffold@localhost commit -q -m "the tree" --no-verify

# ROBOT pure: a problem of pure functions (scripts/new-problem KEY --pure), 3 points, no program.
if [ "$robot" = pure ]; then kind=(--pure) points=3; else kind=(--simulated "$robot") points=6; fi
bash "$copy/scripts/new-problem" "$key" "${kind[@]}" || fail "scripts/new-problem $key ${kind[*]} failed"
echo "made problem $key ($(seconds))"

# Nothing outside the problem's four places.
outside=$(git -C "$copy" status --porcelain --untracked-files=all |
  awk -v k="$key" '{ p = $2 } p != "problems.txt" && p != "exercises/p" k ".cpp" && p != "solutions/p" k ".cpp" &&
                   index(p, "problems/" k "/") != 1 { print }')
[ -z "$outside" ] || fail "scripts/new-problem changed files outside problem $key's places:
$outside"

export CCACHE_BASEDIR=$copy
cmake --preset release -S "$copy" -DOPSPACE_BUILD_BENCH=OFF "-DOPSPACE_NO_UNITY_PROBLEMS=$key" > "$work/configure.log" 2>&1 ||
  { tail -30 "$work/configure.log"; fail "configuring the copy with problem $key failed ($work/configure.log)"; }
build=$copy/build/release
programs=("hw2-p$key" "hw2-p$key-sol")
[ "$robot" != pure ] || programs=()
cmake --build "$build" --target hw2-grade hw2-grade-sol opspace_runner_loops "${programs[@]}" test_graded_suite \
  > "$work/build.log" 2>&1 || { grep -B2 -A12 "error" "$work/build.log" | head -60; fail "building the copy with problem $key failed ($work/build.log)"; }
echo "built ($(seconds))"

# grade NAME DIR: hw2-grade's report of problem KEY with the exercise files of DIR.
grade() {
  "$build/apps/hw2-grade" --problem "$key" --exercises "$2" --seed 1 --jobs 1 --cache "$work/cache" > "$work/$1.txt" 2>&1 ||
    { cat "$work/$1.txt"; fail "hw2-grade failed on the $1"; }
  grep -E "^Total: " "$work/$1.txt" || { cat "$work/$1.txt"; fail "no total in the $1's report"; }
}
[ "$(grade stub "$copy/exercises")" = "Total: 0 / $points points" ] ||
  { cat "$work/stub.txt"; fail "the stub of problem $key does not score 0 / $points"; }
[ "$(grade solution "$copy/solutions")" = "Total: $points / $points points" ] ||
  { cat "$work/solution.txt"; fail "the solution of problem $key does not earn $points / $points"; }
echo "graded: stub 0 / $points, solution $points / $points ($(seconds))"

# Every case of the graded suite but the other problems' catalogue cases (theirs, unchanged, run in
# the tree's own ctest): the new problem's case, its rubric, the suite's full marks and identities,
# and any case that would ask for a line written by hand for a new problem.
others=""
for k in "${OPSPACE_KEYS[@]}"; do others+="${others:+,}*is named in the report: $k"; done
"$build/tests/mutants/test_graded_suite" -tce="$others" > "$work/suite.txt" 2>&1 ||
  { tail -40 "$work/suite.txt"; fail "the graded suite's checks fail with problem $key"; }
grep -q "test cases: *[1-9]" "$work/suite.txt" || { cat "$work/suite.txt"; fail "the graded suite ran no case for problem $key"; }
echo "the graded suite's checks pass ($(seconds))"

if [ "$robot" != pure ]; then
  "$build/apps/hw2-p$key-sol" --duration 0.1 --csv "$work/run.csv" > "$work/run.txt" 2>&1 || { cat "$work/run.txt"; fail "hw2-p$key-sol failed"; }
  # --live: its folder declares no LAB (a build without the live lab says that instead); before, the
  # program died of an empty std::function ("bad_function_call").
  set +e
  "$build/apps/hw2-p$key-sol" --live > "$work/live.txt" 2>&1
  code=$?
  set -e
  [ $code -eq 2 ] && grep -q "no live lab" "$work/live.txt" ||
    { cat "$work/live.txt"; fail "hw2-p$key-sol --live exited $code, without saying it has no live lab"; }
fi
bash "$copy/tests/docs/check_cited_paths.sh" "$copy" > "$work/cited.txt" 2>&1 || { cat "$work/cited.txt"; fail "a path cited in problem $key's files is missing"; }
echo "PASS: problem $key made, built and graded in $(seconds)"
