#!/usr/bin/env bash
# deploy/build_resources.sh: setup.sh's build parallelism, GCC's collector and the proof's
# parallelism for given memory and CPUs, and the readers of a cgroup's limits on made-up machines
# (a cgroup v2 container, a v1 host, no limit at all).
#   bash tests/scripts/check_build_resources.sh REPO WORK
set -euo pipefail
repo=$1 work=$2
# shellcheck source=/dev/null
source "$repo/deploy/build_resources.sh"
failures=0
expect() {  # expect WHAT GOT WANTED
  if [ "$2" = "$3" ]; then echo "ok: $1: $2"; else echo "FAILED: $1: got '$2', wanted '$3'"; failures=$((failures + 1)); fi
}
mib=1024  # KiB in a MiB

# --- the plan: "JOBS HEAPSIZE_KIB EXPAND UNITY PROOF_JOBS" ------------------------------------------
# Gradescope's default, 768 MB and half a CPU (a quota of half rounds up to 1): one compile, a
# unit per file, the collector early, one proof test (two gradings of 347 MB each would not fit).
expect "768 MB, 1 CPU" "$(opspace_build_plan $((768 * mib)) 1)" "1 65536 20 OFF 1"
# 768 MB with 2 CPUs still compiles one at a time: two early-collecting compiles need 1280 MiB.
expect "768 MB, 2 CPUs" "$(opspace_build_plan $((768 * mib)) 2)" "1 65536 20 OFF 1"
# 1.4 GiB: still under one late-collecting compile's 1.5 GiB; two early ones fit (2 x 640 MiB).
expect "1.4 GiB, 2 CPUs" "$(opspace_build_plan $((1434 * mib)) 2)" "2 65536 20 OFF 3"
# 2 GiB: one compile with the collector from 1 GB on; the proof two per CPU at most.
expect "2 GiB, 1 CPU" "$(opspace_build_plan $((2048 * mib)) 1)" "1 1048576 default ON 2"
# This project's machine, 24 GiB and 2 CPUs: as before issue 59, two compiles, four proof tests.
expect "24 GiB, 2 CPUs" "$(opspace_build_plan $((24576 * mib)) 2)" "2 1048576 default ON 4"
# Less memory than any plan: one compile all the same (it may still fit), never none.
expect "100 MiB, 4 CPUs" "$(opspace_build_plan $((100 * mib)) 4)" "1 65536 20 OFF 1"

# --- the readers, on made-up /proc and /sys/fs/cgroup ------------------------------------------
rm -rf "$work" && mkdir -p "$work"
fake() {  # fake NAME: a /proc with 16 GiB available and 8 CPUs
  mkdir -p "$work/$1/proc/self" "$work/$1/cgroup"
  printf 'MemTotal:       32000000 kB\nMemAvailable:   %s kB\n' $((16384 * 1024)) > "$work/$1/proc/meminfo"
  export OPSPACE_PROC_ROOT=$work/$1/proc OPSPACE_CGROUP_ROOT=$work/$1/cgroup OPSPACE_NPROC=8
}
# A v2 container (cgroup namespace: its path is /) limited to 768 MiB and half a CPU.
fake v2
echo '0::/' > "$OPSPACE_PROC_ROOT/self/cgroup"
echo $((768 * 1024 * 1024)) > "$OPSPACE_CGROUP_ROOT/memory.max"
echo '50000 100000' > "$OPSPACE_CGROUP_ROOT/cpu.max"
expect "v2 container: memory" "$(opspace_memory_kib)" $((768 * mib))
expect "v2 container: CPUs" "$(opspace_cpus)" 1
# A v2 scope under a slice: the slice's lower limit counts, "max" is no limit.
fake v2-nested
echo '0::/build.slice/run.scope' > "$OPSPACE_PROC_ROOT/self/cgroup"
mkdir -p "$OPSPACE_CGROUP_ROOT/build.slice/run.scope"
echo max > "$OPSPACE_CGROUP_ROOT/build.slice/run.scope/memory.max"
echo $((1024 * 1024 * 1024)) > "$OPSPACE_CGROUP_ROOT/build.slice/memory.max"
echo 'max 100000' > "$OPSPACE_CGROUP_ROOT/build.slice/run.scope/cpu.max"
echo '150000 100000' > "$OPSPACE_CGROUP_ROOT/build.slice/cpu.max"
expect "v2 nested: memory" "$(opspace_memory_kib)" $((1024 * mib))
expect "v2 nested: CPUs (1.5 rounded up)" "$(opspace_cpus)" 2
# A v1 host (this project's machines): memory and cpu mounted apart, cpu shared with cpuacct.
fake v1
printf '4:memory:/jobs/one\n2:cpu,cpuacct:/jobs\n0::/\n' > "$OPSPACE_PROC_ROOT/self/cgroup"
mkdir -p "$OPSPACE_CGROUP_ROOT/memory/jobs/one" "$OPSPACE_CGROUP_ROOT/cpu,cpuacct/jobs"
echo 9223372036854771712 > "$OPSPACE_CGROUP_ROOT/memory/memory.limit_in_bytes"
echo 9223372036854771712 > "$OPSPACE_CGROUP_ROOT/memory/jobs/memory.limit_in_bytes"
echo $((768 * 1024 * 1024)) > "$OPSPACE_CGROUP_ROOT/memory/jobs/one/memory.limit_in_bytes"
echo 50000 > "$OPSPACE_CGROUP_ROOT/cpu,cpuacct/jobs/cpu.cfs_quota_us"
echo 100000 > "$OPSPACE_CGROUP_ROOT/cpu,cpuacct/jobs/cpu.cfs_period_us"
expect "v1: memory" "$(opspace_memory_kib)" $((768 * mib))
expect "v1: CPUs" "$(opspace_cpus)" 1
# No limit anywhere: MemAvailable and nproc.
fake none
printf '4:memory:/\n2:cpu,cpuacct:/\n0::/\n' > "$OPSPACE_PROC_ROOT/self/cgroup"
mkdir -p "$OPSPACE_CGROUP_ROOT/memory" "$OPSPACE_CGROUP_ROOT/cpu,cpuacct"
echo 9223372036854771712 > "$OPSPACE_CGROUP_ROOT/memory/memory.limit_in_bytes"
echo -1 > "$OPSPACE_CGROUP_ROOT/cpu,cpuacct/cpu.cfs_quota_us"
echo 100000 > "$OPSPACE_CGROUP_ROOT/cpu,cpuacct/cpu.cfs_period_us"
expect "no limit: memory" "$(opspace_memory_kib)" $((16384 * mib))
expect "no limit: CPUs" "$(opspace_cpus)" 8

[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "all passed"
