# Shared by scripts/grade and scripts/test (sourced, not run): installs the Debian packages
# the build needs when they are missing, configures the release preset once, and builds
# incrementally.
set -euo pipefail

OPSPACE_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OPSPACE_BUILD="$OPSPACE_ROOT/build/release"
# What CMakeLists.txt finds, as Debian packages.
OPSPACE_PACKAGES=(g++ make cmake pkg-config libeigen3-dev doctest-dev libbullet-dev
                  liburdfdom-dev libbenchmark-dev)

opspace_say() { printf 'opspace: %s\n' "$*" >&2; }

opspace_install_packages() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    opspace_say "not a Debian system: install these packages' equivalents yourself: ${OPSPACE_PACKAGES[*]}"
    return 0
  fi
  local missing=() p
  for p in "${OPSPACE_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0

  local as_root=()
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      as_root=(sudo)
    else
      opspace_say "these Debian packages are missing: ${missing[*]}"
      opspace_say "installing them needs root: run this command as root, or install sudo, or run"
      opspace_say "  apt-get install ${missing[*]}"
      exit 1
    fi
  fi
  opspace_say "installing missing Debian packages: ${missing[*]}"
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

opspace_configure() {
  if [ ! -f "$OPSPACE_BUILD/CMakeCache.txt" ]; then
    opspace_say "configuring build/release"
    (cd "$OPSPACE_ROOT" && cmake --preset release >/dev/null)
  fi
}

# opspace_build [cmake --build arguments...], e.g. opspace_build --target hw2-grade
opspace_build() {
  opspace_say "building (incremental)"
  cmake --build "$OPSPACE_BUILD" --parallel "$(nproc)" "$@"
}

opspace_setup() {
  opspace_install_packages
  opspace_configure
}
