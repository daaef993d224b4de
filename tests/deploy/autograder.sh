#!/usr/bin/env bash
# The Gradescope bundle end to end, in a temporary AUTOGRADER_ROOT (what Gradescope does, step
# by step): scripts/autograder writes the zip; it is unzipped into ROOT/source; setup.sh and
# run_autograder are copied to ROOT; setup.sh runs from ROOT/source (installs, builds, proves,
# locks down); then run_autograder grades one submission after another, each in a fresh
# ROOT/submission and ROOT/results:
#   stubs -> 0; the reference -> full marks; the reference with p2.cpp broken -> only 2 at 0;
#   a malformed submission (no exercise file) -> a clear message, a valid results.json, 0;
#   files in a subfolder, a symbolic link, a missing file -> found, refused, graded as the stub;
#   no grader at all -> still a valid results.json that says so.
# As root, setup.sh creates the account opspace-runner on this machine (as on Gradescope).
# With ccache installed (scripts/setup.sh's test packages), setup.sh's build takes each object
# that this tree's build or an earlier run compiled from the same source and flags from ccache's
# store: what it still proves is that the bundle holds everything the grader needs and that
# setup.sh configures, builds, proves (four tests, below) and locks it down; that the sources
# compile, the build of this tree proves. Without ccache it compiles everything.
# One image per bundle: the set-up ROOT lives in IMAGES/<fingerprint> (default
# REPO/build/autograder-images), the fingerprint being the SHA-256 of every file of the zip
# with its path and mode. A second run with the identical bundle (the test run again in the
# same clone: CI's sanitized suite did until issue 50 left it to the release suite) reuses that image, which setup.sh built, proved and
# locked down in the first run, and grades every submission again; any change to a file of the
# bundle, setup.sh and the grader options included, makes a new image. AUTOGRADER_TEST_FRESH=1
# sets up anew regardless.
#   bash tests/deploy/autograder.sh REPO WORK [IMAGES]
set -euo pipefail
repo=$1 work=$2
if command -v ccache > /dev/null 2>&1; then
  export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}
  # Paths under the repository hashed relative to the build folder, so the bundle's copy
  # (inside WORK) matches this tree; precompiled headers need the sloppiness (ccache's manual).
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$repo}
  export CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:-pch_defines,time_macros}
fi
check="$repo/tests/deploy/check_json.cmake"
seconds() { echo $(( $(date +%s) - $1 )); }
images=${3:-$repo/build/autograder-images}
options=(--hidden "in simulation")  # grader options pass through the bundle
# setup.sh's proof, narrowed to one test of each kind it runs (graded, grader, tamper: two, the
# reference's file and the runner's view): this clone's release suite, where this test runs,
# runs all of them once (CI proves each thing once: docs/ci.md). What is left proves that the
# bundle's tree holds the proof, that it runs as setup.sh runs it, and that it passes.
proof_tests=(
  'graded:the reference solutions earn full marks on every graded test'
  'grader: --seed replays'
  'tamper: including the reference solution by its absolute path does not compile'
  'tamper: a runner sees no compiler, assembler or linker'
)
proof="^($(IFS='|'; echo "${proof_tests[*]}"))"
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work"
mkdir -p "$images"
exec 9> "$images/lock"
flock 9  # one run at a time sets up or uses an image
bash "$repo/scripts/autograder" "$work/bundle" -- "${options[@]}"
mkdir -p "$work/unzipped"
(cd "$work/unzipped" && cmake -E tar xf "$work/bundle/autograder.zip")
# A course's own secret files, planted in a problem's grade/ (a note and a nested header, neither
# compiled): setup.sh must remove them with the rest of that folder, by place.
[ -d "$work/unzipped/opspace/problems/1b/grade" ] || { echo "the bundle has no problems/1b/grade/"; exit 1; }
printf 'planted by tests/deploy/autograder.sh: a secret of the course\n' > "$work/unzipped/opspace/problems/1b/grade/planted-secret.md"
mkdir -p "$work/unzipped/opspace/problems/2/grade/helpers"
printf '// planted by tests/deploy/autograder.sh\n' > "$work/unzipped/opspace/problems/2/grade/helpers/planted.hpp"
fingerprint=$(cd "$work/unzipped" && { find . -type f -printf '%m %p\n' | LC_ALL=C sort
  find . -type f -print0 | LC_ALL=C sort -z | xargs -0 sha256sum; } | sha256sum | cut -c1-16)
root="$images/$fingerprint"
if [ "${AUTOGRADER_TEST_FRESH:-}" != 1 ] && [ -f "$root/setup-done" ]; then
  echo "the identical bundle (fingerprint $fingerprint) was set up, proved and locked down by setup.sh at $(cat "$root/setup-done"): grading on that image"
else
  rm -rf "$images"/*/  # an image of an older bundle proves nothing about this one
  mkdir -p "$root"
  mv "$work/unzipped" "$root/source"
  [ -x "$root/source/run_autograder" ] && [ -f "$root/source/setup.sh" ] ||
    { echo "setup.sh and an executable run_autograder must be at the top of the zip"; exit 1; }
  cp "$root/source/run_autograder" "$root/source/setup.sh" "$root/"
  start=$(date +%s)
  (cd "$root/source" && AUTOGRADER_ROOT="$root" OPSPACE_SETUP_PROOF="$proof" bash ./setup.sh)
  grep -q "100% tests passed, 0 tests failed out of ${#proof_tests[@]}\$" "$root/setup-proof.log" ||
    { cat "$root/setup-proof.log"; echo "setup.sh's proof did not run the ${#proof_tests[@]} tests it was given"; exit 1; }
  echo "TIME setup.sh: $(seconds "$start") s (load: $(cut -d' ' -f1-3 /proc/loadavg))"
  date -u '+%Y-%m-%d %H:%M:%S UTC' > "$root/setup-done"
fi
rm -rf "$work/unzipped"
for gone in solutions tests/mutants tests/tamper build/release/apps/hw2-grade-sol build/release/grading-cache/none; do
  [ ! -e "$root/source/opspace/$gone" ] || { echo "setup.sh left $gone"; exit 1; }
done
leftover=$(cd "$root/source/opspace" && find problems -mindepth 2 -maxdepth 2 -name grade -print)
[ -z "$leftover" ] || { echo "setup.sh left a problem's secret side in the image: $leftover"; exit 1; }
# Nor their objects in the build (the graded code's and the suite's), which hold the graded tests'
# strings, oracles and hints. (opspace_graded_visible is the handout's replay of public answers.)
leftover=$(cd "$root/source/opspace/build/release" &&
  find . -type d \( -name opspace_graded_problems.dir -o -name opspace_graded.dir \) -print)
[ -z "$leftover" ] || { echo "setup.sh left the graded code's objects in the image: $leftover"; exit 1; }
rm -rf "$work"/submission-* "$work/stubs"

stubs="$work/stubs"
mkdir -p "$stubs"
for key in "${OPSPACE_KEYS[@]}"; do git -C "$repo" show "HEAD:exercises/p$key.cpp" > "$stubs/p$key.cpp"; done

# grade NAME: grades $work/NAME (the submission) and keeps its results as $work/NAME.json.
grade() {
  rm -rf "$root/submission" "$root/results"
  cp -a "$work/$1" "$root/submission"
  local t0
  t0=$(date +%s)
  AUTOGRADER_ROOT="$root" "$root/run_autograder" > "$work/$1.log" 2>&1 ||
    { cat "$work/$1.log"; echo "run_autograder exited non-zero"; exit 1; }
  echo "TIME run_autograder ($1): $(seconds "$t0") s (load: $(cut -d' ' -f1-3 /proc/loadavg))"
  cp "$root/results/results.json" "$work/$1.json"
}

mkdir -p "$work/submission-stubs"
cp "$stubs"/*.cpp "$work/submission-stubs/"
grade submission-stubs
cmake -DJSON="$work/submission-stubs.json" -DZERO=ALL -P "$check"

mkdir -p "$work/submission-reference"
cp "$repo"/solutions/p*.cpp "$work/submission-reference/"
grade submission-reference
# The grader options of the bundle apply: --hidden "in simulation" hides those tests alone.
cmake -DJSON="$work/submission-reference.json" -DFULL=ALL "-DHIDDEN=in simulation" -P "$check"

mkdir -p "$work/submission-broken"
cp "$repo"/solutions/p*.cpp "$work/submission-broken/"
printf 'this is not C++\n' > "$work/submission-broken/p2.cpp"
grade submission-broken
cmake -DJSON="$work/submission-broken.json" "-DFULL=1a;1b;3;4" -DZERO=2 "-DOUTPUT=exercises/p2.cpp:1:" -P "$check"

mkdir -p "$work/submission-malformed"
printf '%%PDF-1.4\n' > "$work/submission-malformed/answers.pdf"
cp "$repo/solutions/p1a.cpp" "$work/submission-malformed/P1A.CPP"
grade submission-malformed
files=$(printf 'p%s.cpp, ' "${OPSPACE_KEYS[@]}")
cmake -DJSON="$work/submission-malformed.json" -DZERO=ALL \
  "-DOUTPUT=No exercise file was found;'P1A.CPP'.*the grader reads only ${files%, };Ignored.*answers.pdf" \
  -P "$check"

mkdir -p "$work/submission-folder/hw2-main/exercises"
cp "$repo"/solutions/p1a.cpp "$repo"/solutions/p1b.cpp "$repo"/solutions/p2.cpp "$work/submission-folder/hw2-main/exercises/"
ln -s "$repo/solutions/p3.cpp" "$work/submission-folder/hw2-main/exercises/p3.cpp"
printf 'my notes\n' > "$work/submission-folder/README.md"
grade submission-folder
cmake -DJSON="$work/submission-folder.json" "-DFULL=1a;1b;2" "-DZERO=3;4" \
  "-DOUTPUT=found in the folder 'hw2-main/exercises';p3.cpp: .*symbolic link;p4.cpp is missing;Ignored.*README.md" \
  -P "$check"

# No grader: run_autograder still writes a results.json, with a score of 0 and the reason.
grader="$root/source/opspace/build/release/apps/hw2-grade"
mv "$grader" "$grader.away"
trap 'mv "$grader.away" "$grader"' EXIT  # the image stays whole for the next run
grade submission-reference
mv "$grader.away" "$grader"
trap - EXIT
cp "$work/submission-reference.json" "$work/submission-no-grader.json"
cmake -DJSON="$work/submission-no-grader.json" -DEMPTY=ON "-DOUTPUT=could not grade this submission: the grader.*is missing" -P "$check"
echo "the bundle sets up, locks down and grades every kind of submission"
