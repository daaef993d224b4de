#!/usr/bin/env bash
# scripts/setup.sh's package check (opspace_install_packages): dpkg is asked once, and not again
# until its database changes or other packages are wanted. Run on a copy of setup.sh in a
# folder of its own, with a dpkg-query that logs its calls and says every package is installed.
# Usage: check_package_stamp.sh REPO WORK
set -euo pipefail
repo=$1 work=$2
rm -rf "$work" && mkdir -p "$work/scripts" "$work/bin"
cp "$repo/scripts/setup.sh" "$work/scripts/"
cat > "$work/bin/dpkg-query" <<'FAKE'
#!/usr/bin/env bash
echo call >> "$QUERIES"
for p in "${@:3}"; do printf '%s install ok installed\n' "$p"; done
FAKE
chmod +x "$work/bin/dpkg-query"
export PATH="$work/bin:$PATH" QUERIES="$work/queries" OPSPACE_DPKG_STATUS="$work/status"
touch "$OPSPACE_DPKG_STATUS"
sleep 0.01  # the stamp must be newer than the status file, to the file system's time step
check() {  # check ARGUMENTS EXPECTED_QUERIES WHY
  : > "$QUERIES"
  bash -c 'source "$1/scripts/setup.sh"; opspace_install_packages ${2:-}' _ "$work" "$1"
  local n; n=$(wc -l < "$QUERIES")
  [ "$n" -eq "$2" ] || { echo "FAIL: $3: dpkg-query ran $n times, expected $2"; exit 1; }
  echo "ok: $3 ($n queries)"
}
# One query for the required packages, one for the optional ones (setup.sh).
check "" 2 "the first check asks dpkg"
check "" 0 "a second check, dpkg's database unchanged, asks nothing"
sleep 0.01
touch "$OPSPACE_DPKG_STATUS"
check "" 2 "after an install or a removal (the database rewritten) it asks again"
check --tests 2 "other packages wanted (--tests) are asked for"
check --tests 0 "and then remembered"
mkdir -p "$work/build" && echo gnuplot-nox > "$work/build/optional-packages-failed"
check "" 2 "while an optional package is listed as failed, the check is not skipped"
