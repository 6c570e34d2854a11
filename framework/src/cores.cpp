#include "raylab/cores.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace raylab {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// The folder `relative` and each folder above it up to `root`, deepest first: a limit set on any
// of them holds for the process.
std::vector<std::string> folder_and_parents(const std::string& root, std::string relative) {
  std::vector<std::string> folders;
  while (!relative.empty() && relative.back() == '/') relative.pop_back();
  for (;;) {
    folders.push_back(root + relative);
    if (relative.empty()) break;
    const std::size_t slash = relative.find_last_of('/');
    relative.erase(slash == std::string::npos ? 0 : slash);
  }
  return folders;
}

// The smallest quota / period over `folders` (cgroup v2's cpu.max: "max 100000" or
// "50000 100000"; v1's cpu.cfs_quota_us, -1 for none, and cpu.cfs_period_us). Infinity: none.
double smallest_cpu_quota(const std::vector<std::string>& folders, bool version2) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const std::string& folder : folders) {
    double quota = -1.0, period = 0.0;
    if (version2) {
      std::istringstream line(read_text(folder + "/cpu.max"));
      std::string quota_text;
      if (!(line >> quota_text >> period) || quota_text == "max") continue;
      try { quota = std::stod(quota_text); } catch (...) { continue; }
    } else {
      std::istringstream quota_line(read_text(folder + "/cpu.cfs_quota_us"));
      std::istringstream period_line(read_text(folder + "/cpu.cfs_period_us"));
      if (!(quota_line >> quota) || !(period_line >> period)) continue;
    }
    if (quota > 0.0 && period > 0.0) smallest = std::min(smallest, quota / period);
  }
  return smallest;
}

}  // namespace

unsigned usable_cores(unsigned affinity_cores, const std::string& proc_self_cgroup, const std::string& cgroup_root) {
  double quota = std::numeric_limits<double>::infinity();
  // Each line of /proc/self/cgroup: "ID:CONTROLLERS:PATH"; cgroup v2's is "0::PATH".
  std::istringstream lines(proc_self_cgroup);
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const std::string path = line.substr(second + 1);
    if (controllers.empty()) {
      quota = std::min(quota, smallest_cpu_quota(folder_and_parents(cgroup_root, path), true));
      continue;
    }
    std::istringstream names(controllers);
    std::string name;
    bool has_cpu = false;
    while (std::getline(names, name, ',')) has_cpu = has_cpu || name == "cpu";
    if (has_cpu)  // mounted under its own name ("cpu") or the list's ("cpu,cpuacct")
      for (const std::string& mount : {std::string("/cpu"), "/" + controllers})
        quota = std::min(quota, smallest_cpu_quota(folder_and_parents(cgroup_root + mount, path), false));
  }
  unsigned cores = affinity_cores > 0 ? affinity_cores : std::max(1u, std::thread::hardware_concurrency());
  if (std::isfinite(quota)) cores = std::min(cores, static_cast<unsigned>(std::max(1.0, std::ceil(quota - 1e-9))));
  return std::max(1u, cores);
}

unsigned usable_cores() {
#ifdef __linux__
  static const unsigned cores = [] {
    cpu_set_t set;
    CPU_ZERO(&set);
    const unsigned affinity = sched_getaffinity(0, sizeof set, &set) == 0 ? static_cast<unsigned>(CPU_COUNT(&set)) : 0;
    return usable_cores(affinity, read_text("/proc/self/cgroup"), "/sys/fs/cgroup");
  }();
  return cores;
#else
  return std::max(1u, std::thread::hardware_concurrency());
#endif
}

unsigned threads_within_address_space_limit(std::uint64_t limit, std::uint64_t mapped, std::uint64_t stack) {
  constexpr std::uint64_t kArena = std::uint64_t{64} << 20;
  if (limit == 0) return std::numeric_limits<unsigned>::max();
  if (mapped >= limit) return 0;
  return static_cast<unsigned>(std::min<std::uint64_t>((limit - mapped) / (stack + kArena), std::numeric_limits<unsigned>::max()));
}

unsigned threads_within_address_space_limit() {
#ifdef __linux__
  rlimit address_space{}, stack{};
  if (getrlimit(RLIMIT_AS, &address_space) != 0 || address_space.rlim_cur == RLIM_INFINITY)
    return std::numeric_limits<unsigned>::max();
  // glibc gives a new thread RLIMIT_STACK's size, or 2 MiB when that is unlimited.
  std::uint64_t stack_bytes = std::uint64_t{8} << 20;
  if (getrlimit(RLIMIT_STACK, &stack) == 0)
    stack_bytes = stack.rlim_cur == RLIM_INFINITY ? std::uint64_t{2} << 20 : static_cast<std::uint64_t>(stack.rlim_cur);
  std::uint64_t pages = 0;  // the first figure of /proc/self/statm: the mapped size in pages
  std::istringstream(read_text("/proc/self/statm")) >> pages;
  return threads_within_address_space_limit(address_space.rlim_cur,
                                            pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE)), stack_bytes);
#else
  return std::numeric_limits<unsigned>::max();
#endif
}

}  // namespace raylab
