// How many threads a render starts when it is not told: one per core this process may use.
#pragma once

#include <string>

namespace raylab {

// The cores this process may use: those of its CPU affinity (taskset, a container's cpuset), and
// no more than its CPU quota allows, rounded up (a container's cgroup: Gradescope grants half a
// CPU, i.e. 1). std::thread::hardware_concurrency counts every core of the machine instead, and a
// thread beyond the quota only takes time from the others (and memory: its stack). At least 1.
unsigned usable_cores();

// The same from given sources, for the tests: `affinity_cores` as sched_getaffinity counts them
// (0: unknown), `proc_self_cgroup` the text of /proc/self/cgroup, and `cgroup_root` the folder
// where the cgroup file systems are mounted (/sys/fs/cgroup).
unsigned usable_cores(unsigned affinity_cores, const std::string& proc_self_cgroup, const std::string& cgroup_root);

}  // namespace raylab
