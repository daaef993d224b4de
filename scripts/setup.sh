# Shared by scripts/grade and scripts/test (sourced, not run): installs the Debian packages
# the build needs when they are missing, configures the release preset once, and builds
# incrementally.
set -euo pipefail

OPSPACE_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OPSPACE_BUILD="$OPSPACE_ROOT/build/release"
# What CMakeLists.txt finds, as Debian packages. libssl-dev (libcrypto: the SHA-256 of the
# grader's runner cache), libseccomp-dev (the sandbox's system-call filter) and
# nlohmann-json3-dev (results.json, the replay and explorer pages' data) are the grader's;
# libcpp-httplib-dev serves the programs' --live page (docs/live.md; the Gradescope bundle
# leaves it out); libyaml-cpp-dev reads a Gradescope export's submission_metadata.yml
# (scripts/regrade, hw2-class; the bundle leaves it out too); libarchive-dev opens a zip a
# student uploaded, for scripts/regrade (hw2-unzip; the bundle leaves it out: Gradescope unzips).
OPSPACE_PACKAGES=(g++ make cmake ninja-build pkg-config libeigen3-dev doctest-dev libbullet-dev
                  liburdfdom-dev libbenchmark-dev libssl-dev libseccomp-dev nlohmann-json3-dev
                  libcpp-httplib-dev libyaml-cpp-dev libarchive-dev)
# The autograder's pictures: cairo draws each failed simulated test's plot into results.json,
# in DejaVu Sans, and libpng writes it (grader/trusted/report/plot_png.hpp). Where the reference is
# (the instructor's repository, the Gradescope bundle); a student handout has no simulated test
# and its grader draws no picture, so a student does not install them (CMakeLists.txt).
OPSPACE_GRADER_PICTURE_PACKAGES=(libcairo2-dev libpng-dev fonts-dejavu-core)
if [ -d "$OPSPACE_ROOT/solutions" ]; then
  OPSPACE_PACKAGES+=("${OPSPACE_GRADER_PICTURE_PACKAGES[@]}")
fi
# The pictures of a run (docs/visuals.md): gnuplot draws the plots (fonts for its PNGs), node
# and npm bundle the 3D replay viewer at build time (npm fetches over TLS: ca-certificates).
# Optional: if they cannot be installed, the build, the grader and the programs still work and
# say which picture they skipped.
OPSPACE_OPTIONAL_PACKAGES=(gnuplot-nox ca-certificates)
[ -d "$OPSPACE_ROOT/solutions" ] || OPSPACE_OPTIONAL_PACKAGES+=(fonts-dejavu-core)  # else required, above
# Only the tests need a browser: Chromium runs the replay and explorer tests (scripts/test
# installs it; a student's scripts/grade does not download it). Emscripten (em++) compiles the
# library to WebAssembly for the explorer page (docs/visuals.md). Optional too: without them
# those tests are skipped. ccache lets CI's builds (the release tree, the handout's, the
# Gradescope bundle's, the sanitized one) share their compiles (docs/ci.md); without it they
# compile everything.
OPSPACE_TEST_PACKAGES=(chromium emscripten ccache)
# A node/npm already on the machine (for example from NodeSource) is kept: Debian's npm
# package would conflict with it.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  OPSPACE_OPTIONAL_PACKAGES+=(nodejs npm)
fi

# dpkg's database, rewritten by every install and removal (tests/scripts/check_package_stamp.sh
# points it elsewhere).
OPSPACE_DPKG_STATUS="${OPSPACE_DPKG_STATUS:-/var/lib/dpkg/status}"

opspace_say() { printf 'opspace: %s\n' "$*" >&2; }

# 1 once opspace_install_packages has installed something (opspace_configure then runs CMake
# again in an existing build folder).
OPSPACE_INSTALLED=0

# opspace_missing PACKAGE...: prints those not installed. One dpkg-query for all of them: every
# grade asks, and a query per package cost 0.3-3 s of an edit graded again (docs/performance.md).
opspace_missing() {
  local line p installed=" "
  while IFS= read -r line; do
    [[ "$line" == *" install ok installed" ]] && installed+="${line%% *} "
  done < <(dpkg-query -W -f='${Package} ${Status}\n' "$@" 2>/dev/null || true)
  for p in "$@"; do
    [[ "$installed" == *" $p "* ]] || printf '%s\n' "$p"
  done
}

# opspace_install_packages [--tests]: the required packages, the optional ones, and with
# --tests those only the tests need.
opspace_install_packages() {
  local wanted=("${OPSPACE_OPTIONAL_PACKAGES[@]}")
  [ "${1:-}" = --tests ] && wanted+=("${OPSPACE_TEST_PACKAGES[@]}")
  if ! command -v dpkg-query >/dev/null 2>&1; then
    opspace_say "not a Debian system: install these packages' equivalents yourself: ${OPSPACE_PACKAGES[*]}"
    opspace_say "and, for plots and the 3D replay: ${wanted[*]}"
    return 0
  fi
  # Optional packages that could not be installed once (listed in this file) are not retried
  # on every command.
  local optional_failed="$OPSPACE_ROOT/build/optional-packages-failed"
  # A check that found every package is remembered (this file: the packages it checked) until
  # dpkg's database changes: an install or a removal rewrites /var/lib/dpkg/status. Its two
  # queries were 0.06 s of every grade (issue 50).
  local present="$OPSPACE_ROOT/build/packages-present" checked="${OPSPACE_PACKAGES[*]} ${wanted[*]}" line=""
  if [ -f "$present" ] && [ "$present" -nt "$OPSPACE_DPKG_STATUS" ] && [ ! -e "$optional_failed" ]; then
    IFS= read -r line < "$present" || true
    [ "$line" = "$checked" ] && return 0
  fi
  local missing optional
  mapfile -t missing < <(opspace_missing "${OPSPACE_PACKAGES[@]}")
  mapfile -t optional < <(opspace_missing "${wanted[@]}")
  if [ ${#missing[@]} -eq 0 ] && [ ${#optional[@]} -eq 0 ] && [ -f "$OPSPACE_DPKG_STATUS" ]; then
    mkdir -p "$(dirname "$present")" && printf '%s\n' "$checked" > "$present"
  fi
  if [ -f "$optional_failed" ] && [ ${#optional[@]} -gt 0 ]; then
    mapfile -t optional < <(printf '%s\n' "${optional[@]}" | grep -vxF -f "$optional_failed" || true)
  fi
  [ ${#missing[@]} -eq 0 ] && [ ${#optional[@]} -eq 0 ] && return 0

  local as_root=()
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      as_root=(sudo)
    elif [ ${#missing[@]} -gt 0 ]; then
      opspace_say "these Debian packages are missing: ${missing[*]}"
      opspace_say "installing them needs root: run this command as root, or install sudo, or run"
      opspace_say "  apt-get install ${missing[*]}"
      exit 1
    else
      opspace_say "without root, not installing ${optional[*]}: plots or the 3D replay may be skipped"
      return 0
    fi
  fi
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq ||
    opspace_say "apt-get update failed; trying with the package lists at hand"
  OPSPACE_INSTALLED=1
  if [ ${#missing[@]} -gt 0 ]; then
    opspace_say "installing missing Debian packages: ${missing[*]}"
    "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
  if [ ${#optional[@]} -gt 0 ]; then
    opspace_say "installing Debian packages for plots and the 3D replay: ${optional[*]}"
    local apt_install=("${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends)
    if ! "${apt_install[@]}" "${optional[@]}"; then
      # apt-get installs all or nothing: one at a time, so that one failure costs only itself.
      local p failed=()
      for p in "${optional[@]}"; do "${apt_install[@]}" "$p" || failed+=("$p"); done
      if [ ${#failed[@]} -gt 0 ]; then
        opspace_say "could not install ${failed[*]}: the programs skip the pictures, and the tests the checks, that need them (docs/visuals.md)"
        opspace_say "(not retried; delete $optional_failed to try again)"
        mkdir -p "$(dirname "$optional_failed")" && printf '%s\n' "${failed[@]}" >> "$optional_failed"
      fi
    fi
  fi
}

opspace_configure() {
  if [ ! -f "$OPSPACE_BUILD/CMakeCache.txt" ]; then
    opspace_say "configuring build/release"
    (cd "$OPSPACE_ROOT" && cmake --preset release >/dev/null)
  elif [ "$OPSPACE_INSTALLED" = 1 ]; then
    # What CMake did not find before (em++ after `bash scripts/grade` then `bash scripts/test`)
    # may be there now: CMake looks again for what it had not found. -S/-B, not the preset: a
    # folder made with another generator keeps it.
    opspace_say "configuring build/release again: packages were installed"
    cmake -S "$OPSPACE_ROOT" -B "$OPSPACE_BUILD" >/dev/null
  fi
}

# opspace_build [cmake --build arguments...], e.g. opspace_build --target hw2-grade
opspace_build() {
  opspace_say "building (incremental)"
  cmake --build "$OPSPACE_BUILD" --parallel "$(nproc)" "$@"
}

# opspace_setup [--tests]: packages (see opspace_install_packages), then configure.
opspace_setup() {
  opspace_install_packages "$@"
  opspace_configure
}
