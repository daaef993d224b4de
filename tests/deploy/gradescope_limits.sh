#!/usr/bin/env bash
# Proves the Gradescope bundle under Gradescope's default resources, 768 MB of memory and half a
# CPU: setup.sh (install, build, the whole proof, lockdown) and then run_autograder on the
# reference, on one wrong file and on the untouched stubs, every one of them inside one cgroup
# with those limits, and no compiler cache (Gradescope has none). It checks that setup.sh
# finished, chose one compile at a time with GCC's collector set early (deploy/build_resources.sh),
# and that each submission was graded within 60 s with the expected total; and it reports the
# times, each compile's peak memory, the cgroup's peak and OOM kills, and the load.
# Run by hand (docs/instructor.md, "Gradescope's memory and CPU"): it took 23 minutes on this
# project's 2-core machine, too long for CI, which runs tests/scripts/check_build_resources.sh
# (the plan for given memory) instead. Needs root (cgroups, setup.sh's account).
#
#   bash tests/deploy/gradescope_limits.sh [--memory MIB] [--cpu PERCENT] [--ubuntu2204] [--dir DIR]
#     --memory MIB   the memory limit (default 768: Docker's 768m, in MiB)
#     --cpu PERCENT  the CPU quota, in percent of one CPU (default 50)
#     --ubuntu2204   build with g++ 11 and Debian 11's Bullet 3.06 and nlohmann-json laid
#                    over /usr in a private mount namespace, as scripts/ubuntu2204-check does
#                    (run that first: it downloads them into build/ubuntu2204/root)
#     --dir DIR      its work folder (default build/gradescope-limits); the image goes to DIR/root
#
# The cgroup, created by hand and removed at the end: version 1 (this project's machines: memory
# and cpu controllers mounted apart), under this process's own cgroup of each; or version 2 (one
# hierarchy), a child of its root. The v2 path has not run on the project's machines, which are v1.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
memory_mib=768 cpu_percent=50 ubuntu=false dir=$repo/build/gradescope-limits
while [ $# -gt 0 ]; do
  case "$1" in
    --memory) memory_mib=${2:?}; shift 2 ;;
    --cpu) cpu_percent=${2:?}; shift 2 ;;
    --ubuntu2204) ubuntu=true; shift ;;
    --dir) dir=${2:?}; shift 2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "gradescope_limits: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
start=$SECONDS
say() { printf 'gradescope_limits (%ss): %s\n' "$((SECONDS - start))" "$*"; }
die() { say "FAILED: $*"; exit 1; }
[ "$(id -u)" -eq 0 ] || die "needs root (cgroups, and setup.sh creates an account)"
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
overlay=$repo/build/ubuntu2204/root

# --- Ubuntu 22.04's toolchain: the whole run in a mount namespace with the overlay -------------
if $ubuntu && [ "${OPSPACE_LIMITS_INSIDE:-}" != 1 ]; then
  [ -d "$overlay/usr" ] || die "$overlay is missing: run bash scripts/ubuntu2204-check first"
  # shellcheck disable=SC2016 # $1 and $@ are the inner shell's
  OPSPACE_LIMITS_INSIDE=1 exec unshare --mount --propagation private -- \
    bash -c 'mount -t overlay opspace-ubuntu2204 -o "lowerdir=$1/usr:/usr" /usr && shift && exec bash "$@"' \
    _ "$overlay" "${BASH_SOURCE[0]}" --memory "$memory_mib" --cpu "$cpu_percent" --ubuntu2204 --dir "$dir"
fi
if $ubuntu; then
  export CXX=g++-11  # CMake's compiler for a new build folder
  command -v g++-11 > /dev/null || die "g++-11 is missing (scripts/ubuntu2204-check installs it)"
fi

# --- the bundle, unzipped as Gradescope does ------------------------------------------------------
root=$dir/root
rm -rf "$root" "$dir/bundle"
bash "$repo/scripts/autograder" "$dir/bundle" > /dev/null 2>&1 || die "scripts/autograder failed"
mkdir -p "$root/source"
(cd "$root/source" && cmake -E tar xf "$dir/bundle/autograder.zip")
cp "$root/source/run_autograder" "$root/source/setup.sh" "$root/"

# Each compile's peak memory and time, through the launcher setup.sh takes from the environment.
mkdir -p "$dir/bin"
compiles=$dir/compiles.log
: > "$compiles"
cat > "$dir/bin/opspace-measure-compile" << EOF
#!/bin/sh
exec /usr/bin/time -a -o "$compiles" -f '%M KiB %e s %U s user: %C' "\$@"
EOF
chmod +x "$dir/bin/opspace-measure-compile"
[ -x /usr/bin/time ] || die "/usr/bin/time is missing (Debian's package time)"

# --- the cgroup -----------------------------------------------------------------------------------
name=opspace-limits-$$
limit=$((memory_mib * 1024 * 1024))
period=100000 quota=$((cpu_percent * 1000))
v1_memory="" v1_cpu="" v2=""
if [ -f /sys/fs/cgroup/cgroup.controllers ]; then
  v2=/sys/fs/cgroup/$name
  if ! grep -qw memory /sys/fs/cgroup/cgroup.subtree_control || ! grep -qw cpu /sys/fs/cgroup/cgroup.subtree_control; then
    die "the memory and cpu controllers are not enabled for /sys/fs/cgroup's children"
  fi
  mkdir "$v2"
  echo "$limit" > "$v2/memory.max"
  echo 0 > "$v2/memory.swap.max" 2> /dev/null || true
  echo "$quota $period" > "$v2/cpu.max"
  procs=("$v2/cgroup.procs")
else
  own() { sed -n "s/^[0-9]*:\\([^:]*,\\)\\{0,1\\}$1\\(,[^:]*\\)\\{0,1\\}:\\(.*\\)\$/\\3/p" /proc/self/cgroup | head -1; }
  v1_memory=/sys/fs/cgroup/memory$(own memory)
  v1_memory=${v1_memory%/}/$name
  v1_cpu=/sys/fs/cgroup/cpu$(own cpu)
  v1_cpu=${v1_cpu%/}/$name
  if [ ! -d "$(dirname "$v1_memory")" ] || [ ! -d "$(dirname "$v1_cpu")" ]; then
    die "no cgroup v1 memory and cpu hierarchies under /sys/fs/cgroup"
  fi
  mkdir "$v1_memory" "$v1_cpu"
  echo "$limit" > "$v1_memory/memory.limit_in_bytes"
  echo "$limit" > "$v1_memory/memory.memsw.limit_in_bytes" 2> /dev/null || true  # no swap
  echo "$period" > "$v1_cpu/cpu.cfs_period_us"
  echo "$quota" > "$v1_cpu/cpu.cfs_quota_us"
  procs=("$v1_memory/cgroup.procs" "$v1_cpu/cgroup.procs")
fi
cleanup() {
  local d
  for d in "$v2" "$v1_memory" "$v1_cpu"; do [ -n "$d" ] && [ -d "$d" ] && rmdir "$d" 2> /dev/null; done
  return 0
}
trap cleanup EXIT
peak_mib() {
  if [ -n "$v2" ]; then echo $(($(cat "$v2/memory.peak" 2> /dev/null || echo 0) / 1048576))
  else echo $(($(cat "$v1_memory/memory.max_usage_in_bytes") / 1048576)); fi
}
reset_peak() {
  if [ -n "$v2" ]; then echo 0 > "$v2/memory.peak" 2> /dev/null || true
  else echo 0 > "$v1_memory/memory.max_usage_in_bytes"; fi
}
oom_kills() {
  if [ -n "$v2" ]; then sed -n 's/^oom_kill //p' "$v2/memory.events"
  else sed -n 's/^oom_kill //p' "$v1_memory/memory.oom_control"; fi
}
throttled() {
  if [ -n "$v2" ]; then sed -n 's/^throttled_usec //p' "$v2/cpu.stat" | awk '{ printf "%d s", $1 / 1e6 }'
  else sed -n 's/^throttled_time //p' "$v1_cpu/cpu.stat" | awk '{ printf "%d s", $1 / 1e9 }'; fi
}
# in_limits COMMAND...: runs it inside the cgroup (its children stay there).
in_limits() {
  # shellcheck disable=SC2016 # the inner shell's
  bash -c 'for f in "${@:2:$1}"; do echo $$ > "$f"; done; shift $(($1 + 1)); exec "$@"' _ "${#procs[@]}" "${procs[@]}" "$@"
}
say "cgroup ${v2:-$v1_memory and $v1_cpu}: ${memory_mib} MiB, ${cpu_percent} % of a CPU; $($ubuntu && echo "g++ 11 and Debian 11's Bullet laid over /usr" || echo "this machine's g++ and Bullet")"

# --- setup.sh -----------------------------------------------------------------------------------
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
setup_start=$SECONDS
status=0
(cd "$root/source" && in_limits env -u OPSPACE_SETUP_PROOF -u CCACHE_DIR PATH="$dir/bin:$PATH" \
   CMAKE_CXX_COMPILER_LAUNCHER=opspace-measure-compile AUTOGRADER_ROOT="$root" bash ./setup.sh) > "$dir/setup.log" 2>&1 || status=$?
setup_seconds=$((SECONDS - setup_start))
setup_peak=$(peak_mib) setup_ooms=$(oom_kills)
grep -E '^opspace setup' "$dir/setup.log" | sed 's/^/  /'
[ "$status" -eq 0 ] || { tail -30 "$dir/setup.log"; die "setup.sh failed (exit $status, log: $dir/setup.log)"; }
grep -q "1 compile(s) at once, GCC's ggc-min-heapsize 65536 KiB and ggc-min-expand 20 %, unity units OFF" "$dir/setup.log" ||
  [ "$memory_mib" -gt 1280 ] || die "setup.sh did not choose one compile with GCC collecting early"
biggest=$(sort -n "$compiles" | tail -1 | cut -d' ' -f1-6)
say "setup.sh: $setup_seconds s; the cgroup's peak $setup_peak MiB (page cache included), OOM kills ${setup_ooms:-?}, throttled $(throttled); $(wc -l < "$compiles") compiles, the largest peak: $biggest; load $load_before -> $(cut -d' ' -f1-3 /proc/loadavg)"

# --- run_autograder -------------------------------------------------------------------------------
grade() {  # grade NAME EXPECTED-SCORE FILES...: one submission, timed
  local name=$1 expected=$2
  shift 2
  rm -rf "$root/submission" "$root/results"
  mkdir -p "$root/submission"
  cp "$@" "$root/submission/"
  reset_peak
  local t0=$SECONDS load
  load=$(cut -d' ' -f1 /proc/loadavg)
  in_limits env AUTOGRADER_ROOT="$root" bash "$root/run_autograder" > "$dir/grade-$name.log" 2>&1
  local seconds=$((SECONDS - t0))
  local score
  score=$(sed -n 's/^{"score": *\([0-9.]*\).*/\1/p; s/^ *"score": *\([0-9.]*\),*$/\1/p' "$root/results/results.json" | head -1)
  say "run_autograder, $name: score ${score:-none} in $seconds s; the cgroup's peak $(peak_mib) MiB, OOM kills $(oom_kills); load $load -> $(cut -d' ' -f1 /proc/loadavg)"
  [ "$score" = "$expected" ] || die "$name: score '$score', expected $expected (results: $root/results/results.json)"
  [ "$seconds" -le 60 ] || die "$name took $seconds s, more than Gradescope's 60 s asked for here"
}
grade reference 97 "$repo"/solutions/p*.cpp
# The reference with problem 1a's file replaced by its stub: 1a's 23 points lost.
mkdir -p "$dir/one-wrong"
cp "$repo"/solutions/p*.cpp "$dir/one-wrong/"
cp "$repo/exercises/p1a.cpp" "$dir/one-wrong/p1a.cpp"
grade one-stub 74 "$dir"/one-wrong/p*.cpp
grade stubs 0 "$repo"/exercises/p*.cpp
say "passed: setup.sh and run_autograder under ${memory_mib} MiB and ${cpu_percent} % of a CPU"
