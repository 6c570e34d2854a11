#!/usr/bin/env bash
# tools/gradescope/resources.sh, which run_autograder asks what the container grants: the memory
# limit and CPU quota of its cgroup, v2 or v1, on its own folder or one above it, read from faked
# cgroup folders and /proc/self/cgroup texts. (instructor_gradescope_pipeline runs it in a real
# cgroup v1 of 768 MB.) Usage: check_gradescope_resources.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$(realpath "$1"); work=$(realpath -m "$2")
rm -rf "$work"; mkdir -p "$work"
# shellcheck source=../../tools/gradescope/resources.sh
source "$source_dir/tools/gradescope/resources.sh"
failures=0
expect() {  # WHAT ACTUAL EXPECTED
  [ "$2" = "$3" ] || { echo "FAIL: $1: $2, expected $3"; failures=$((failures + 1)); }
}
machine_mb=$(awk '/^MemTotal:/ {print int($2 / 1024)}' /proc/meminfo)
cores=$(nproc)
at_most_cores() { [ "$1" -le "$cores" ] && echo "$1" || echo "$cores"; }
put() { mkdir -p "$(dirname "$work/$1")"; echo "$2" > "$work/$1"; }

# cgroup v2, Gradescope's default: 768 MB, half a CPU.
put v2/docker/abc/memory.max 805306368
put v2/docker/abc/cpu.max "50000 100000"
echo "0::/docker/abc" > "$work/v2.cgroup"
expect "v2 memory" "$(memory_limit_mb "$work/v2" "$work/v2.cgroup")" 768
expect "v2 CPUs" "$(cpu_limit "$work/v2" "$work/v2.cgroup")" 1
# A limit on a folder above, none ("max") on the process's own.
put v2p/memory.max 1073741824
put v2p/job/memory.max max
put v2p/cpu.max "300000 100000"
put v2p/job/cpu.max "max 100000"
echo "0::/job" > "$work/v2p.cgroup"
expect "v2 memory above" "$(memory_limit_mb "$work/v2p" "$work/v2p.cgroup")" 1024
expect "v2 CPUs above" "$(cpu_limit "$work/v2p" "$work/v2p.cgroup")" "$(at_most_cores 3)"
# cgroup v1, the CPU controller mounted as cpu,cpuacct; v1's "no limit" is about 2^63.
put v1/memory/docker/abc/memory.limit_in_bytes 1610612736
put v1/memory/memory.limit_in_bytes 9223372036854771712
put "v1/cpu,cpuacct/docker/abc/cpu.cfs_quota_us" 200000
put "v1/cpu,cpuacct/docker/abc/cpu.cfs_period_us" 100000
printf '11:memory:/docker/abc\n4:cpu,cpuacct:/docker/abc\n1:name=systemd:/docker/abc\n' > "$work/v1.cgroup"
expect "v1 memory" "$(memory_limit_mb "$work/v1" "$work/v1.cgroup")" 1536
expect "v1 CPUs" "$(cpu_limit "$work/v1" "$work/v1.cgroup")" "$(at_most_cores 2)"
put "v1/cpu,cpuacct/docker/abc/cpu.cfs_quota_us" -1
expect "v1 without a quota" "$(cpu_limit "$work/v1" "$work/v1.cgroup")" "$cores"
# No cgroup files at all: the machine's.
expect "no cgroup: memory" "$(memory_limit_mb "$work/none" /dev/null)" "$machine_mb"
expect "no cgroup: CPUs" "$(cpu_limit "$work/none" /dev/null)" "$cores"

if [ $failures -gt 0 ]; then echo "check_gradescope_resources: $failures failures"; exit 1; fi
echo "check_gradescope_resources: memory and CPU limits read from cgroup v2 and v1, on the process's folder and above"
