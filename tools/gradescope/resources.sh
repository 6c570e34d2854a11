# What the container grants a run (sourced by run_autograder): Gradescope gives 768 MB and half a
# CPU by default, and a course may raise both; `nproc` and /proc/meminfo show the whole host.
#   memory_limit_mb [CGROUP_ROOT [PROC_SELF_CGROUP]]  the smallest memory limit of this process's
#       cgroups (v2 memory.max, v1 memory.limit_in_bytes, on its own folder and each above it,
#       and at the root of the container's view), and the machine's memory; in MB (MiB)
#   cpu_limit [CGROUP_ROOT [PROC_SELF_CGROUP]]        the CPUs of the affinity (nproc), no more
#       than the cgroup's CPU quota rounded up (v2 cpu.max, v1 cpu.cfs_quota_us / cfs_period_us)
# The arguments stand in for /sys/fs/cgroup and /proc/self/cgroup in the kit's own tests.

# The folders to look in for a cgroup controller's files: MOUNT's folder for each path that
# PROC_SELF_CGROUP names for CONTROLLER ("" for v2), with every folder above it.
_cgroup_folders() {  # CGROUP_ROOT PROC_SELF_CGROUP CONTROLLER
  local root=$1 proc=$2 controller=$3 line ids names path mounts mount
  [ -r "$proc" ] || return 0
  while IFS= read -r line; do
    ids=${line%%:*}; names=${line#*:}; path=${names#*:}; names=${names%%:*}
    [ -n "$ids" ] || continue
    if [ -z "$controller" ]; then
      [ -z "$names" ] || continue
      mounts=("$root")
    else
      case ",$names," in *",$controller,"*) ;; *) continue ;; esac
      mounts=("$root/$controller" "$root/$names")
    fi
    for mount in "${mounts[@]}"; do
      while :; do
        path=${path%/}
        echo "$mount$path"
        [ -n "$path" ] || break
        path=${path%/*}
      done
      path=${line#*:}; path=${path#*:}
    done
  done < "$proc"
}

memory_limit_mb() {
  local root=${1:-/sys/fs/cgroup} proc=${2:-/proc/self/cgroup} folder value limit
  limit=$(awk '/^MemTotal:/ {print int($2 / 1024)}' /proc/meminfo 2>/dev/null)
  [ -n "$limit" ] || limit=4096
  while IFS= read -r folder; do
    for value in $(cat "$folder/memory.max" "$folder/memory.limit_in_bytes" 2>/dev/null); do
      case "$value" in ''|*[!0-9]*) continue ;; esac
      [ ${#value} -lt 16 ] || continue  # v1's "no limit" is about 2^63
      value=$((value / 1048576))
      [ "$value" -ge "$limit" ] || limit=$value
    done
  done < <(_cgroup_folders "$root" "$proc" ""; _cgroup_folders "$root" "$proc" memory)
  echo "$limit"
}

cpu_limit() {
  local root=${1:-/sys/fs/cgroup} proc=${2:-/proc/self/cgroup} folder quota period cpus limit
  limit=$(nproc 2>/dev/null || echo 1)
  while IFS= read -r folder; do
    quota=""; period=""
    if [ -r "$folder/cpu.max" ]; then
      read -r quota period < "$folder/cpu.max" || true
    elif [ -r "$folder/cpu.cfs_quota_us" ] && [ -r "$folder/cpu.cfs_period_us" ]; then
      quota=$(cat "$folder/cpu.cfs_quota_us"); period=$(cat "$folder/cpu.cfs_period_us")
    fi
    case "$quota$period" in ''|*[!0-9]*) continue ;; esac  # "max", -1 or unreadable: no quota
    [ "$quota" -gt 0 ] && [ "$period" -gt 0 ] || continue
    cpus=$(( (quota + period - 1) / period ))
    [ "$cpus" -ge "$limit" ] || limit=$cpus
  done < <(_cgroup_folders "$root" "$proc" ""; _cgroup_folders "$root" "$proc" cpu)
  echo "$limit"
}
