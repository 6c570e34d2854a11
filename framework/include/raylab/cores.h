// How many threads a render starts when it is not told: one per core this process may use.
#pragma once

#include <cstdint>
#include <string>

namespace raylab {

// The cores this process may use: those of its CPU affinity (taskset, a container's cpuset), and
// no more than its CPU quota allows, rounded up (a container's cgroup: Gradescope grants half a
// CPU, i.e. 1). std::thread::hardware_concurrency counts every core of the machine instead, and a
// thread beyond the quota only takes time from the others (and memory: its stack). At least 1.
unsigned usable_cores();

// How many threads fit the address-space limit (RLIMIT_AS; the grader's stage servers run under
// one) beside what the process already maps: each new thread needs its stack and may get a malloc
// arena of its own (glibc reserves 64 MiB of address space for one). Without a limit: no bound.
// A render that is not told its thread count starts no more than this (at least 1), so that a
// machine with many cores does not make it fail to start threads under a small limit.
unsigned threads_within_address_space_limit();

// The same from given figures, in bytes (limit 0: none).
unsigned threads_within_address_space_limit(std::uint64_t limit, std::uint64_t mapped, std::uint64_t stack);

// The same from given sources, for the tests: `affinity_cores` as sched_getaffinity counts them
// (0: unknown), `proc_self_cgroup` the text of /proc/self/cgroup, and `cgroup_root` the folder
// where the cgroup file systems are mounted (/sys/fs/cgroup).
unsigned usable_cores(unsigned affinity_cores, const std::string& proc_self_cgroup, const std::string& cgroup_root);

}  // namespace raylab
