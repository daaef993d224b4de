# shellcheck shell=bash
# How many compiles setup.sh runs at once, and how GCC's collector is set for them, from the
# memory and CPU the image build really has (sourced by deploy/setup.sh; tested by
# tests/scripts/check_build_resources.sh). Gradescope gives a container 768 MB and half a CPU
# by default, and a container's /proc/meminfo and nproc show the host's: its cgroup's limits
# are what count.
#
#   opspace_memory_kib   the memory it may use (KiB): the lowest limit of its cgroup and every
#                        cgroup above it (v2 memory.max, v1 memory.limit_in_bytes), and
#                        MemAvailable, whichever is lower
#   opspace_cpus         the CPUs it may use: nproc, lowered by a CPU quota (v2 cpu.max, v1
#                        cpu.cfs_quota_us / cpu.cfs_period_us) rounded up
#   opspace_build_plan MEMORY_KIB CPUS
#                        prints "JOBS HEAPSIZE_KIB EXPAND UNITY PROOF_JOBS": the build's
#                        parallelism, GCC's ggc-min-heapsize and ggc-min-expand for our units
#                        (EXPAND "default": GCC's own), OPSPACE_UNITY_BUILD (ON or OFF), and how
#                        many proof tests run at once
#
# OPSPACE_CGROUP_ROOT (default /sys/fs/cgroup), OPSPACE_PROC_ROOT (default /proc) and
# OPSPACE_NPROC let the test point the readers at a made-up machine.

# The numbers, measured with g++ 11 on the library's two unity units and on their files one by
# one (docs/instructor.md, "Gradescope's memory and CPU"):
# - With the collector from 1 GB on (the top CMakeLists.txt's default) the library's simulation
#   unit peaks at 947 MiB (1147 MB with g++ 12 for the largest, docs/performance.md): a compile
#   is given 1.5 GiB.
opspace_big_job_kib=$((1536 * 1024))
# - Below that, the grade path's libraries are compiled one unit per file (OPSPACE_UNITY_BUILD
#   OFF) and GCC collects from 64 MB on and at each 20 % of growth: the same unit whole peaked at
#   699 MiB even so (783 MiB with GCC's defaults, 645 MiB collecting from 32 MB at each 10 %; the
#   algorithms unit 834 MiB), the largest file alone at 431 MiB. A compile is given 640 MiB:
#   under 768 MiB, one at a time, with room for ninja, the shell and the kernel's cache of the
#   headers.
opspace_small_heap_kib=65536
opspace_small_expand=20
opspace_small_job_kib=$((640 * 1024))
# - A proof test (a grading: the grader, then a student file compiled against the precompiled
#   Eigen, then the runner) peaked at 347 MB in issue 59's measurement: 400 MiB each.
opspace_proof_job_kib=$((400 * 1024))

# _opspace_cgroup_paths CONTROLLER: this process's cgroup folder for it and every folder above,
# up to the hierarchy's root, one per line (nothing when none is found).
_opspace_cgroup_paths() {
  local root=${OPSPACE_CGROUP_ROOT:-/sys/fs/cgroup} proc=${OPSPACE_PROC_ROOT:-/proc}
  local line hierarchy controllers path base=""
  while IFS= read -r line; do
    hierarchy=${line%%:*}; line=${line#*:}; controllers=${line%%:*}; path=${line#*:}
    if [ "$1" = v2 ] && [ "$hierarchy" = 0 ] && [ -z "$controllers" ]; then
      base=$root
    elif [ "$1" != v2 ] && [[ ",$controllers," == *",$1,"* ]]; then
      # v1: each controller's own mount, or one shared with others (cpu,cpuacct).
      base=$root/$1
      [ -d "$base" ] || base=$root/$controllers
    else
      continue
    fi
    # Inside a container with a cgroup namespace the path is / and base is its own cgroup.
    while :; do
      [ -d "$base$path" ] && printf '%s\n' "$base${path%/}"
      [ "$path" = / ] || [ -z "$path" ] && break
      path=$(dirname "$path")
    done
    return 0
  done < "$proc/self/cgroup" 2> /dev/null
}

opspace_memory_kib() {
  local proc=${OPSPACE_PROC_ROOT:-/proc} best="" value dir
  value=$(awk '/^MemAvailable:/ { print $2 }' "$proc/meminfo" 2> /dev/null)
  [[ "$value" =~ ^[0-9]+$ ]] && best=$value
  while IFS= read -r dir; do
    value=$(cat "$dir/memory.max" 2> /dev/null) || continue
    [[ "$value" =~ ^[0-9]+$ ]] || continue  # "max": no limit there
    value=$((value / 1024))
    if [ -z "$best" ] || [ "$value" -lt "$best" ]; then best=$value; fi
  done < <(_opspace_cgroup_paths v2)
  while IFS= read -r dir; do
    value=$(cat "$dir/memory.limit_in_bytes" 2> /dev/null) || continue
    [[ "$value" =~ ^[0-9]+$ ]] || continue
    # v1 says "no limit" with a number near 2^63: it is larger than any MemAvailable.
    [ "${#value}" -lt 19 ] || continue
    value=$((value / 1024))
    if [ -z "$best" ] || [ "$value" -lt "$best" ]; then best=$value; fi
  done < <(_opspace_cgroup_paths memory)
  printf '%s\n' "${best:-0}"
}

opspace_cpus() {
  local cpus=${OPSPACE_NPROC:-$(nproc)} dir quota period limit
  while IFS= read -r dir; do
    [ -r "$dir/cpu.max" ] || continue
    read -r quota period < "$dir/cpu.max" || continue
    if ! [[ "$quota" =~ ^[0-9]+$ && "$period" =~ ^[1-9][0-9]*$ ]]; then continue; fi  # "max": none
    limit=$(((quota + period - 1) / period))
    [ "$limit" -ge "$cpus" ] || cpus=$limit
  done < <(_opspace_cgroup_paths v2)
  while IFS= read -r dir; do
    quota=$(cat "$dir/cpu.cfs_quota_us" 2> /dev/null) || continue
    period=$(cat "$dir/cpu.cfs_period_us" 2> /dev/null) || continue
    if ! [[ "$quota" =~ ^[0-9]+$ && "$period" =~ ^[1-9][0-9]*$ ]]; then continue; fi  # -1: none
    limit=$(((quota + period - 1) / period))
    [ "$limit" -ge "$cpus" ] || cpus=$limit
  done < <(_opspace_cgroup_paths cpu)
  [ "$cpus" -ge 1 ] || cpus=1
  printf '%s\n' "$cpus"
}

opspace_build_plan() {
  local memory=$1 cpus=$2 jobs heap=1048576 expand=default unity=ON proof
  [ "$cpus" -ge 1 ] || cpus=1
  jobs=$((memory / opspace_big_job_kib))
  if [ "$jobs" -lt 1 ]; then
    # Not even one compile with the collector late: a unit per file, GCC collecting early, and
    # as many compiles as fit at their smaller peak.
    heap=$opspace_small_heap_kib expand=$opspace_small_expand unity=OFF
    jobs=$((memory / opspace_small_job_kib))
  fi
  [ "$jobs" -le "$cpus" ] || jobs=$cpus
  [ "$jobs" -ge 1 ] || jobs=1
  # The proof: two tests per CPU (a tamper case mostly waits), as many as the memory holds.
  proof=$((memory / opspace_proof_job_kib))
  [ "$proof" -le $((2 * cpus)) ] || proof=$((2 * cpus))
  [ "$proof" -ge 1 ] || proof=1
  printf '%s %s %s %s %s\n' "$jobs" "$heap" "$expand" "$unity" "$proof"
}
