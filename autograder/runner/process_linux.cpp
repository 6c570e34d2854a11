// stage_process.h on Linux.
//
// Confinement of a stage server (set up between fork and exec, so the judge's own files and
// memory are never touched by stage code):
//   - as root: its own uid and gid (1000000000 + the judge's pid, no other process has them), so
//     it cannot write any file of the grader, the repository or the reference data, cannot
//     signal the judge, RLIMIT_NPROC holds (the kernel never applies it to uid 0), and
//     everything it starts, detached or not, is killed at once with kill(-1) by a helper that
//     takes the same uid (atomic against fork: a fork bomb cannot outrun it). When that uid
//     could not enter the programs' folder or the scenes (a checkout under /root or a 0700
//     home), it keeps one capability, CAP_DAC_READ_SEARCH (read and search any folder; no
//     writes, no signals, no other privilege), as an ambient capability across the exec;
//   - not root: the same user, so the judge is a child subreaper and kills every descendant it
//     finds in /proc until none is left (a setsid() grandchild still has the judge as ancestor);
//   - as root, where the kernel allows it: network and IPC namespaces of its own (no network;
//     no System V shared memory or message queues, which RLIMIT_AS does not count and which
//     would outlive it: enter_own_namespaces), and a PID namespace whose process 1 is the judge's
//     (start_in_own_pid_namespace: the stage sees no other process, and everything in the
//     namespace dies with the server, or with the judge);
//   - as root, where the kernel has the memory and pids controllers and lets the judge make a
//     cgroup beneath its own (v1 or v2): a cgroup of its own per stage server (StageCgroup), whose
//     memory limit counts everything it holds (page cache, memfds, pipe buffers, tmpfs: RLIMIT_AS
//     counts only its address space), without swap, and whose pids.max bounds its processes and
//     threads; a stage that reaches the limit is killed by the kernel and loses the call with the
//     limit's name (crash_memory_limit);
//   - both: Landlock where the kernel has it (no file may be created or written anywhere, files
//     read only beneath the system's folders, the scenes and the server's own program: not the
//     reference data, solutions/ or private cases; no TCP, no signals to processes outside the
//     sandbox: stage_ruleset), RLIMIT_NPROC, RLIMIT_AS, RLIMIT_FSIZE (the
//     output limit; stdout and stderr go to a memfd; it bounds each memfd the stage makes too),
//     RLIMIT_NOFILE (kMaxOpenFiles), no core dumps, parent-death signal, only
//     descriptors 0-4 open.
#include "stage_process.h"
#include "kit_folders.h"

#include "landlock.h"

#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <linux/capability.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace raylab::grading {
namespace {

// Where the judge makes a cgroup of its own for each stage server (version 0: nowhere).
struct Cgroups {
  int version = 0;  // 1 or 2
  std::string memory_parent, pids_parent;  // the folders to make a stage's cgroup in (v2: the same)
};

struct Sandbox {
  bool as_root = false;
  uid_t uid = 0;  // the sandbox's own uid and gid, when as_root
  bool keeps_read_search = false;  // as_root, and the uid alone cannot reach the programs
  bool own_namespaces = false;     // as_root, and the kernel gives it network, IPC and PID namespaces
  int landlock = 0;
  Cgroups cgroups;  // as_root only
};

// The descriptors a stage server may have open at once: its five, and room for files it reads
// (a scene, a mesh). Each could hold a memfd or a pipe's buffer, memory outside RLIMIT_AS.
constexpr rlim_t kMaxOpenFiles = 64;

// In the child, as root, before setuid: a network namespace of its own (no interface but a
// loopback that is down: no UDP or TCP out, no abstract sockets shared with the machine) and an
// IPC namespace of its own with no room for System V shared memory segments or message queues,
// nor POSIX message queues (memory that RLIMIT_AS does not count, which would outlive the
// stage). The namespaces end with the stage's last process. Only system calls.
bool enter_own_namespaces() {
  if (::unshare(CLONE_NEWNET | CLONE_NEWIPC) != 0) return false;
  for (const char* limit : {"/proc/sys/kernel/shmmni", "/proc/sys/kernel/msgmni", "/proc/sys/fs/mqueue/queues_max"}) {
    const int fd = ::open(limit, O_WRONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool written = ::write(fd, "0\n", 2) == 2;
    ::close(fd);
    if (!written) return false;
  }
  return true;
}

// fork() as a system call alone (no handlers of the C library), with `flags` added: CLONE_NEWPID
// makes the child process 1 of a PID namespace of its own. Only system calls follow in the child.
pid_t fork_process(unsigned long flags) {
  return static_cast<pid_t>(::syscall(SYS_clone, flags | SIGCHLD, nullptr, nullptr, nullptr, nullptr));
}

// Process 1 of the stage's PID namespace (as root, where the kernel gives it one): starts the stage
// server as process 2 (returns 0 in it), then only reaps, and when the server ends writes its wait
// status to `report` for the judge and exits: the kernel then kills everything else in the
// namespace, detached or not, and it dies with the judge (parent-death signal), so nothing of a
// stage outlives the judge even when the judge is killed. It runs as root (no stage process may
// signal it) and holds no descriptor but `report`. Only system calls.
pid_t start_in_own_pid_namespace(int report) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  const pid_t server = fork_process(0);
  if (server <= 0) return server;  // the server (0), or a failure the caller reports
  if (::dup2(report, 0) < 0) ::_exit(126);
  ::close_range(1, ~0u, 0);
  for (;;) {
    int status = 0;
    const pid_t done = ::waitpid(-1, &status, 0);
    if (done < 0 && errno == EINTR) continue;
    if (done < 0) ::_exit(0);
    if (done == server) {
      [[maybe_unused]] const ssize_t written = ::write(0, &status, sizeof status);
      ::_exit(0);
    }
  }
}

// In the child, after setuid: keep CAP_DAC_READ_SEARCH alone, in the permitted, effective,
// inheritable and ambient sets, so that it survives the exec (PR_SET_KEEPCAPS was set before
// the setuid). Only system calls: this runs between fork and exec.
bool keep_only_read_search() {
  __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
  __user_cap_data_struct data[2] = {};
  const unsigned bit = 1u << (CAP_DAC_READ_SEARCH % 32);
  data[CAP_DAC_READ_SEARCH / 32].effective = data[CAP_DAC_READ_SEARCH / 32].permitted = bit;
  data[CAP_DAC_READ_SEARCH / 32].inheritable = bit;
  if (::syscall(SYS_capset, &header, data) != 0) return false;
  return ::prctl(PR_CAP_AMBIENT, PR_CAP_AMBIENT_RAISE, CAP_DAC_READ_SEARCH, 0, 0) == 0;
}
Sandbox& sandbox() {
  static Sandbox value;
  return value;
}

// Processes whose real uid is `uid` (for RLIMIT_NPROC, which counts them all).
int processes_of(uid_t uid) {
  int count = 0;
  DIR* proc = ::opendir("/proc");
  if (!proc) return 0;
  while (const dirent* entry = ::readdir(proc)) {
    if (entry->d_name[0] < '0' || entry->d_name[0] > '9') continue;
    std::ifstream status(std::string("/proc/") + entry->d_name + "/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("Uid:", 0) == 0) {
        count += std::stoul(line.substr(4)) == uid;
        break;
      }
  }
  ::closedir(proc);
  return count;
}

// Every process below the judge: (pid -> parent) from /proc, then the judge's subtree.
std::vector<pid_t> descendants_of(pid_t root) {
  std::map<pid_t, pid_t> parent;
  DIR* proc = ::opendir("/proc");
  if (!proc) return {};
  while (const dirent* entry = ::readdir(proc)) {
    if (entry->d_name[0] < '0' || entry->d_name[0] > '9') continue;
    std::ifstream stat(std::string("/proc/") + entry->d_name + "/stat");
    std::string text;
    std::getline(stat, text);
    const std::size_t close = text.rfind(')');  // the command name may hold spaces and parentheses
    if (close == std::string::npos) continue;
    char state = 0;
    int ppid = 0;
    if (std::sscanf(text.c_str() + close + 1, " %c %d", &state, &ppid) == 2) parent[std::atoi(entry->d_name)] = ppid;
  }
  ::closedir(proc);
  std::set<pid_t> below{root};
  std::vector<pid_t> found;
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& [pid, ppid] : parent)
      if (below.count(ppid) && !below.count(pid)) {
        below.insert(pid);
        found.push_back(pid);
        grew = true;
      }
  }
  return found;
}

void reap_all_children() {
  for (;;) {
    int status = 0;
    const pid_t done = ::waitpid(-1, &status, 0);
    if (done < 0 && errno == EINTR) continue;
    if (done < 0) return;  // ECHILD: none left
  }
}

// Kills everything the stage code started. The stage server itself is already reaped.
void kill_every_descendant() {
  if (sandbox().as_root) {
    // A helper with the sandbox's uid sends SIGKILL to every process it may signal: exactly
    // the sandbox's processes, in one pass that a concurrent fork cannot slip through.
    const pid_t killer = ::fork();
    if (killer == 0) {
      if (::setgid(sandbox().uid) != 0 || ::setuid(sandbox().uid) != 0) ::_exit(1);
      ::kill(-1, SIGKILL);
      ::_exit(0);
    }
    // Orphans of the sandbox are the judge's children (subreaper): reap them and the helper.
    reap_all_children();
    return;
  }
  for (int round = 0; round < 1000; ++round) {
    const std::vector<pid_t> below = descendants_of(::getpid());
    if (below.empty()) break;
    for (pid_t pid : below) ::kill(pid, SIGKILL);
    for (;;) {  // reap what has died; the others are reparented to the judge and found next round
      int status = 0;
      if (::waitpid(-1, &status, WNOHANG) <= 0) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  for (;;) {
    int status = 0;
    if (::waitpid(-1, &status, WNOHANG) <= 0) break;
  }
}

// A signal that ended a stage server, named for a student.
Message signal_description(int signal_number) {
  struct Named {
    int number;
    const char* name;
    MessageId meaning;
  };
  static constexpr Named kSignals[] = {
      {SIGSEGV, "SIGSEGV", MessageId::signal_segv}, {SIGBUS, "SIGBUS", MessageId::signal_bus},
      {SIGFPE, "SIGFPE", MessageId::signal_fpe},    {SIGILL, "SIGILL", MessageId::signal_ill},
      {SIGABRT, "SIGABRT", MessageId::signal_abrt}, {SIGKILL, "SIGKILL", MessageId::signal_kill},
      {SIGXCPU, "SIGXCPU", MessageId::signal_xcpu}, {SIGXFSZ, "SIGXFSZ", MessageId::signal_xfsz},
      {SIGTERM, "SIGTERM", MessageId::signal_term}, {SIGPIPE, "SIGPIPE", MessageId::signal_pipe},
      {SIGTRAP, "SIGTRAP", MessageId::signal_trap}, {SIGSYS, "SIGSYS", MessageId::signal_sys}};
  std::vector<Message> named, advice;
  // The signal's name as the code knows it, and what it means in the run's language (not
  // strsignal(), whose words are the C library's, in English).
  for (const Named& known : kSignals)
    if (known.number == signal_number) named.push_back({MessageId::crash_name, {{"name", known.name}, {"meaning", known.meaning}}});
  if (signal_number == SIGSEGV) advice.push_back(MessageId::crash_advice_memory);
  else if (signal_number == SIGFPE) advice.push_back(MessageId::crash_advice_division);
  else if (signal_number == SIGABRT) advice.push_back(MessageId::crash_advice_abort);
  else if (signal_number == SIGKILL || signal_number == SIGXCPU) advice.push_back(MessageId::crash_advice_killed);
  return {MessageId::crash_signal, {{"number", std::to_string(signal_number)}, {"name", named}, {"advice", advice}}};
}

[[noreturn]] void child_fail(const char* what) {
  const int saved = errno;
  const char* reason = std::strerror(saved);
  [[maybe_unused]] ssize_t ignored = ::write(2, "stage server setup failed: ", 27);
  ignored = ::write(2, what, std::strlen(what));
  ignored = ::write(2, ": ", 2);
  ignored = ::write(2, reason, std::strlen(reason));
  ignored = ::write(2, "\n", 1);
  ::_exit(126);
}

// The stage server's Landlock ruleset, made in the judge before the fork (adding a rule opens its
// path): no file created or written anywhere, no TCP, no signals out, and files read (or run) only
// beneath the system's folders, the kit's scenes and the server's own program. So stage code
// cannot read the reference data (autograder/reference/), solutions/, private cases, the course's
// seed or the other programs of the build (the reference's stage servers). -1 without Landlock.
int stage_ruleset(int abi, const std::string& program) {
  if (abi <= 0) return -1;
  landlock::RulesetAttr attr{landlock::kWriteAccess | landlock::kReadAccess, 0, 0};
  if (abi >= 2) attr.handled_access_fs |= landlock::kReferAccess;
  if (abi >= 3) attr.handled_access_fs |= landlock::kTruncateAccess;
  if (abi >= 4) attr.handled_access_net = landlock::kNetAccess;
  if (abi >= 6) attr.scoped = landlock::kScopes;
  const int ruleset = landlock::create_ruleset(attr, abi);
  if (ruleset < 0) throw std::runtime_error(std::string("landlock_create_ruleset failed: ") + std::strerror(errno));
  std::vector<std::string> readable = {"/usr", "/lib", "/lib32", "/lib64", "/libx32", "/bin", "/sbin",
                                       "/etc", "/dev", "/proc", "/sys", program};
  readable.push_back(std::string(kit_source_folder()) + "/scenes");
  for (const std::string& path : readable) {
    const int fd = ::open(path.c_str(), O_PATH | O_CLOEXEC);
    if (fd < 0) continue;  // (a folder this system does not have)
    struct stat status {};
    const bool folder = ::fstat(fd, &status) == 0 && S_ISDIR(status.st_mode);
    const bool added = landlock::add_path_rule(ruleset, fd, folder ? landlock::kReadAccess : landlock::kReadAccess & landlock::kFileAccess);
    ::close(fd);
    if (!added) {
      ::close(ruleset);
      throw std::runtime_error("landlock_add_rule failed for " + path + ": " + std::strerror(errno));
    }
  }
  return ruleset;
}

bool write_text(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  const int write_error = errno;  // (the caller reports it: close must not replace it)
  ::close(fd);
  errno = write_error;
  return written;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::string text, line;
  while (std::getline(in, line)) text += line + "\n";
  return text;
}

// The judge's own cgroup in the v1 hierarchy of `controller`, or ("") in the unified (v2) one, as
// /proc/self/cgroup names it; "" when it has none there.
std::string own_cgroup(const std::string& controller) {
  std::ifstream in("/proc/self/cgroup");
  for (std::string line; std::getline(in, line);) {
    const std::size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = "," + line.substr(first + 1, second - first - 1) + ",";
    const bool match = controller.empty() ? controllers == ",," && line.compare(0, first, "0") == 0
                                          : controllers.find("," + controller + ",") != std::string::npos;
    if (match) return line.substr(second + 1);
  }
  return "";
}

bool can_make_cgroup_in(const std::string& folder) {
  const std::string probe = folder + "/raylab-probe-" + std::to_string(::getpid());
  if (::mkdir(probe.c_str(), 0700) != 0) return false;
  ::rmdir(probe.c_str());
  return true;
}

// Removes the empty stage cgroups that a judge which was killed left in `folder`.
void remove_stale_stage_cgroups(const std::string& folder) {
  DIR* listing = ::opendir(folder.c_str());
  if (!listing) return;
  const std::string prefix = "raylab-stage-";
  while (const dirent* entry = ::readdir(listing)) {
    const std::string name = entry->d_name;
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const pid_t judge = static_cast<pid_t>(std::atol(name.c_str() + prefix.size()));
    if (judge > 0 && ::kill(judge, 0) != 0 && errno == ESRCH) ::rmdir((folder + "/" + name).c_str());
  }
  ::closedir(listing);
}

// Where this judge (as root) can make a stage's cgroup: beneath its own cgroup in the v1 memory
// and pids hierarchies, else beneath its own v2 cgroup where memory and pids are already enabled
// for children (the judge cannot enable them there itself: a v2 cgroup with processes of its own
// may not). Nowhere else: a cgroup outside the judge's would escape the judge's own limits (a
// container's).
Cgroups find_cgroups() {
  Cgroups found;
  const std::string memory = own_cgroup("memory"), pids = own_cgroup("pids");
  // (In a container the hierarchy's mount is often the judge's own cgroup, not the machine's root,
  // and the path /proc/self/cgroup names is not beneath it.)
  const auto folder_of = [](const std::string& mount, const std::string& path) {
    return ::access((mount + path).c_str(), F_OK) == 0 ? mount + path : mount;
  };
  if (!memory.empty() && !pids.empty()) {
    found.memory_parent = folder_of("/sys/fs/cgroup/memory", memory);
    found.pids_parent = folder_of("/sys/fs/cgroup/pids", pids);
    if (::access((found.memory_parent + "/memory.limit_in_bytes").c_str(), W_OK) == 0 &&
        ::access((found.pids_parent + "/cgroup.procs").c_str(), F_OK) == 0 && can_make_cgroup_in(found.memory_parent) &&
        can_make_cgroup_in(found.pids_parent)) {
      found.version = 1;
      remove_stale_stage_cgroups(found.memory_parent);
      remove_stale_stage_cgroups(found.pids_parent);
      return found;
    }
  }
  const std::string unified = own_cgroup("");
  if (!unified.empty() && ::access("/sys/fs/cgroup/cgroup.controllers", F_OK) == 0) {
    const std::string folder = "/sys/fs/cgroup" + (unified == "/" ? std::string() : unified);
    const std::string enabled = " " + read_text(folder + "/cgroup.subtree_control");
    if (enabled.find(" memory") != std::string::npos && enabled.find(" pids") != std::string::npos &&
        can_make_cgroup_in(folder)) {
      found.version = 2;
      found.memory_parent = found.pids_parent = folder;
      remove_stale_stage_cgroups(folder);
      return found;
    }
  }
  return {};
}

// A stage server's own cgroup (one folder in v2, one per hierarchy in v1): made with its limits
// before the fork, joined by the child before anything else (writing 0 to each cgroup.procs it
// was given open), and removed when the stage has stopped.
class StageCgroup {
 public:
  StageCgroup(const Cgroups& where, const SandboxLimits& limits) {
    const int version = where.version;
    if (version == 0) return;
    static std::atomic<unsigned> serial{0};
    const std::string name = "/raylab-stage-" + std::to_string(::getpid()) + "-" + std::to_string(++serial);
    const std::string memory = limits.memory_limit_mb > 0
                                   ? std::to_string(static_cast<long long>(limits.memory_limit_mb) * 1024 * 1024)
                                   : std::string(version == 1 ? "-1" : "max");
    // (process 1 of the stage's PID namespace is one task more than the stage's own)
    const std::string tasks = limits.max_processes > 0 ? std::to_string(limits.max_processes + 1) : "max";
    bool made = true;
    if (version == 1) {
      made = make(where.memory_parent + name) && write_text(folders_.back() + "/memory.limit_in_bytes", memory);
      // without swap (where the kernel accounts it): both limits the same
      if (made && ::access((folders_.back() + "/memory.memsw.limit_in_bytes").c_str(), W_OK) == 0)
        made = write_text(folders_.back() + "/memory.memsw.limit_in_bytes", memory);
      events_ = folders_.empty() ? "" : folders_.front() + "/memory.oom_control";
      made = made && make(where.pids_parent + name) && write_text(folders_.back() + "/pids.max", tasks);
    } else {
      made = make(where.memory_parent + name) && write_text(folders_.back() + "/memory.max", memory) &&
             write_text(folders_.back() + "/pids.max", tasks);
      if (made && ::access((folders_.back() + "/memory.swap.max").c_str(), W_OK) == 0)
        made = write_text(folders_.back() + "/memory.swap.max", "0");
      events_ = folders_.empty() ? "" : folders_.front() + "/memory.events";
    }
    for (const std::string& folder : folders_) {
      if (!made) break;
      procs_.push_back(::open((folder + "/cgroup.procs").c_str(), O_WRONLY | O_CLOEXEC));
      made = procs_.back() >= 0;
    }
    if (!made) {
      const std::string error = std::strerror(errno);
      remove();
      throw std::runtime_error("could not make the stage's cgroup in " + where.memory_parent + ": " + error);
    }
  }
  StageCgroup(const StageCgroup&) = delete;
  StageCgroup& operator=(const StageCgroup&) = delete;
  ~StageCgroup() { remove(); }

  // In the child, before anything else: only system calls.
  bool join() const {
    for (const int fd : procs_)
      if (::write(fd, "0", 1) != 1) return false;
    return true;
  }
  // In the judge once the child has joined: the descriptors are no longer needed.
  void close_procs() {
    for (const int fd : procs_) ::close(fd);
    procs_.clear();
  }
  // Whether the kernel killed a process of the stage for reaching the memory limit.
  bool killed_for_memory() const {
    if (events_.empty()) return false;
    std::istringstream events(read_text(events_));
    for (std::string key; events >> key;) {
      long long count = 0;
      if (!(events >> count)) break;
      if (key == "oom_kill" && count > 0) return true;
    }
    return false;
  }
  // Once every process of the stage has ended (a killed process may take a moment to leave).
  void remove() {
    close_procs();
    for (auto folder = folders_.rbegin(); folder != folders_.rend(); ++folder)
      for (int attempt = 0; attempt < 1000 && ::rmdir(folder->c_str()) != 0 && errno == EBUSY; ++attempt)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    folders_.clear();
  }

 private:
  bool make(const std::string& folder) {
    if (::mkdir(folder.c_str(), 0700) != 0) return false;
    folders_.push_back(folder);
    return true;
  }

  std::vector<std::string> folders_;
  std::vector<int> procs_;
  std::string events_;  // the file whose "oom_kill" counts the processes the kernel killed for memory
};

}  // namespace

// Whether a process with the sandbox's uid can read and enter every folder the stage server
// needs: the programs' folder (the server and the image module) and the source tree (scenes,
// meshes). A checkout under a folder only root may enter (/root, a 0700 home) cannot be, and
// then the server keeps CAP_DAC_READ_SEARCH (keep_only_read_search). It must never keep
// uid 0: root is exempt from RLIMIT_NPROC, and a fork bomb would take the whole machine.
static bool sandbox_uid_can_reach(uid_t uid) {
  std::vector<std::string> folders;
  char self[4096];
  const ssize_t length = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if (length > 0) {
    const std::string path(self, static_cast<std::size_t>(length));
    folders.push_back(path.substr(0, path.find_last_of('/') + 1));
  }
  folders.push_back(std::string(kit_source_folder()) + "/scenes");
  const pid_t probe = ::fork();
  if (probe < 0) return false;
  if (probe == 0) {
    if (::setgroups(0, nullptr) != 0 || ::setgid(uid) != 0 || ::setuid(uid) != 0) ::_exit(1);
    for (const std::string& folder : folders)
      if (::access(folder.c_str(), R_OK | X_OK) != 0) ::_exit(1);
    ::_exit(0);
  }
  int status = 0;
  while (::waitpid(probe, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

void limit_judge_memory(long megabytes) {
  if (megabytes <= 0) return;
  struct rlimit memory {};
  ::getrlimit(RLIMIT_AS, &memory);
  const rlim_t bytes = static_cast<rlim_t>(megabytes) * 1024 * 1024;
  memory.rlim_cur = memory.rlim_max == RLIM_INFINITY ? bytes : std::min(bytes, memory.rlim_max);
  ::setrlimit(RLIMIT_AS, &memory);
}

void prepare_judge() {
  ::prctl(PR_SET_CHILD_SUBREAPER, 1);
  ::signal(SIGPIPE, SIG_IGN);
  Sandbox& box = sandbox();
  box.uid = static_cast<uid_t>(1000000000u + static_cast<unsigned>(::getpid()));
  box.as_root = ::geteuid() == 0;
  box.keeps_read_search = box.as_root && !sandbox_uid_can_reach(box.uid);
  box.landlock = landlock::abi();
  if (box.as_root) {  // whether this kernel (or container) lets it have the namespaces
    const pid_t probe = ::fork();
    if (probe == 0) ::_exit(::unshare(CLONE_NEWPID) == 0 && enter_own_namespaces() ? 0 : 1);
    int status = 0;
    while (probe > 0 && ::waitpid(probe, &status, 0) < 0 && errno == EINTR) {
    }
    box.own_namespaces = probe > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    box.cgroups = find_cgroups();
  }
}

std::string default_stage_server_path() {
  return std::filesystem::canonical("/proc/self/exe").string() + "-stage-server";
}

int stage_cgroup_version() { return sandbox().cgroups.version; }

Message sandbox_description() {
  const Sandbox& box = sandbox();
  std::vector<Message> parts = {box.as_root ? MessageId::sandbox_own_user : MessageId::sandbox_your_user};
  if (box.keeps_read_search) parts.push_back(MessageId::sandbox_reads_every_folder);
  parts.push_back(box.own_namespaces ? MessageId::sandbox_own_namespaces : MessageId::sandbox_shared_namespaces);
  if (box.cgroups.version > 0)
    parts.push_back({MessageId::sandbox_cgroup, {{"version", std::to_string(box.cgroups.version)}}});
  else
    parts.push_back(MessageId::sandbox_no_cgroup);
  if (box.landlock > 0) {
    std::vector<Message> tcp, signals;
    if (box.landlock >= 4) tcp.push_back(MessageId::sandbox_no_tcp);
    if (box.landlock >= 6) signals.push_back(MessageId::sandbox_no_signals);
    parts.push_back({MessageId::sandbox_landlock, {{"abi", std::to_string(box.landlock)}, {"tcp", tcp}, {"signals", signals}}});
  } else if (!box.as_root) {
    parts.push_back(MessageId::sandbox_no_landlock);
  }
  return {MessageId::sandbox, {{"parts", parts}}};
}

struct StageProcess::Child {
  pid_t pid = -1;
  int output_fd = -1;  // the memfd that holds what the server printed
  long output_limit_bytes = 0;
  int end_report_fd = -1;  // with a PID namespace: pid is its process 1, which writes here how the
                           // server (its process 2) ended
  std::unique_ptr<StageCgroup> cgroup;  // where the judge has cgroups
  long memory_limit_mb = 0;
};

StageProcess::StageProcess() = default;

bool StageProcess::running() const { return child_ != nullptr; }

StageProcess::~StageProcess() {
  if (running()) {
    std::string ignored;
    stop(true, ignored);
  }
}

void StageProcess::start(const std::string& program, const SandboxLimits& limits) {
  int requests[2], replies[2];
  if (::pipe2(requests, O_CLOEXEC) != 0 || ::pipe2(replies, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("pipe failed: ") + std::strerror(errno));
  const int output = ::memfd_create("raylab-stage-output", MFD_CLOEXEC);
  if (output < 0) throw std::runtime_error(std::string("memfd_create failed: ") + std::strerror(errno));
  const Sandbox box = sandbox();
  const int nproc = box.as_root ? limits.max_processes : processes_of(::getuid()) + limits.max_processes;
  const pid_t judge = ::getpid();
  const std::string path = program;
  char* const argv[] = {const_cast<char*>(path.c_str()), nullptr};
  const int ruleset = stage_ruleset(box.landlock, path);
  constexpr int kRulesetFd = 5;  // where the child keeps it until it restricts itself

  int end_report[2] = {-1, -1};  // process 1 of the stage's PID namespace -> the judge: how the server ended
  if (box.own_namespaces && ::pipe2(end_report, O_CLOEXEC) != 0) {
    if (ruleset >= 0) ::close(ruleset);
    throw std::runtime_error(std::string("pipe failed: ") + std::strerror(errno));
  }

  std::unique_ptr<StageCgroup> cgroup;
  try {
    if (box.cgroups.version > 0) cgroup = std::make_unique<StageCgroup>(box.cgroups, limits);
  } catch (...) {
    if (ruleset >= 0) ::close(ruleset);
    for (const int fd : end_report)
      if (fd >= 0) ::close(fd);
    throw;
  }

  const pid_t pid = box.own_namespaces ? fork_process(CLONE_NEWPID) : ::fork();
  if (pid < 0) {
    const int error = errno;
    if (ruleset >= 0) ::close(ruleset);
    for (const int fd : end_report)
      if (fd >= 0) ::close(fd);
    throw std::runtime_error(std::string("fork failed: ") + std::strerror(error));
  }
  if (pid == 0) {
    // The child: only system calls from here to exec. First into the stage's cgroup, so that
    // everything it starts is in it.
    if (cgroup && !cgroup->join()) child_fail("joining the stage's cgroup");
    if (box.own_namespaces && start_in_own_pid_namespace(end_report[1]) < 0) child_fail("fork in the PID namespace");
    ::setsid();
    const int null_fd = ::open("/dev/null", O_RDONLY);
    // Move the descriptors out of the way of 0-5 first, then into place.
    const int in = ::fcntl(requests[0], F_DUPFD, 100), out = ::fcntl(replies[1], F_DUPFD, 100);
    const int text = ::fcntl(output, F_DUPFD, 100), nul = ::fcntl(null_fd, F_DUPFD, 100);
    const int rules = ruleset >= 0 ? ::fcntl(ruleset, F_DUPFD, 100) : -1;
    if (in < 0 || out < 0 || text < 0 || nul < 0 || (ruleset >= 0 && rules < 0)) child_fail("dup");
    if (::dup2(nul, 0) < 0 || ::dup2(text, 1) < 0 || ::dup2(text, 2) < 0 || ::dup2(in, 3) < 0 || ::dup2(out, 4) < 0 ||
        (rules >= 0 && ::dup2(rules, kRulesetFd) < 0))
      child_fail("dup2");
    ::close_range(rules >= 0 ? kRulesetFd + 1 : kRulesetFd, ~0u, 0);
    const struct rlimit no_core{0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core);
    if (limits.memory_limit_mb > 0) {
      const rlim_t bytes = static_cast<rlim_t>(limits.memory_limit_mb) * 1024 * 1024;
      const struct rlimit memory{bytes, bytes};
      ::setrlimit(RLIMIT_AS, &memory);
    } else {  // none of its own: not the judge's either (limit_judge_memory set only the soft limit)
      struct rlimit memory {};
      ::getrlimit(RLIMIT_AS, &memory);
      memory.rlim_cur = memory.rlim_max;
      ::setrlimit(RLIMIT_AS, &memory);
    }
    const struct rlimit file_size{static_cast<rlim_t>(limits.output_limit_bytes), static_cast<rlim_t>(limits.output_limit_bytes)};
    ::setrlimit(RLIMIT_FSIZE, &file_size);  // also bounds each memfd it makes
    const struct rlimit open_files{kMaxOpenFiles, kMaxOpenFiles};
    ::setrlimit(RLIMIT_NOFILE, &open_files);
    ::signal(SIGXFSZ, SIG_IGN);  // over the output limit: writes fail, the program goes on
    if (box.as_root) {
      if (box.own_namespaces && !enter_own_namespaces()) child_fail("unshare");
      if (box.keeps_read_search && ::prctl(PR_SET_KEEPCAPS, 1, 0, 0, 0) != 0) child_fail("keepcaps");
      if (::setgroups(0, nullptr) != 0 || ::setgid(box.uid) != 0 || ::setuid(box.uid) != 0) child_fail("setuid");
      if (box.keeps_read_search && !keep_only_read_search()) child_fail("capset");
    }
    const struct rlimit processes{static_cast<rlim_t>(nproc), static_cast<rlim_t>(nproc)};
    ::setrlimit(RLIMIT_NPROC, &processes);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // after setuid, which clears it
    if (::getppid() != (box.own_namespaces ? 1 : judge)) ::_exit(125);
    if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) child_fail("no_new_privs");
    if (rules >= 0) {
      if (!landlock::restrict_self(kRulesetFd)) child_fail("landlock_restrict_self");
      ::close(kRulesetFd);
    }
    ::execv(argv[0], argv);
    child_fail("exec of the stage server");
  }
  ::close(requests[0]);
  ::close(replies[1]);
  if (ruleset >= 0) ::close(ruleset);
  if (end_report[1] >= 0) ::close(end_report[1]);
  if (cgroup) cgroup->close_procs();
  child_ = std::make_unique<Child>(Child{pid, output, limits.output_limit_bytes, end_report[0], std::move(cgroup),
                                         limits.memory_limit_mb});
  request_fd_ = requests[1];
  reply_fd_ = replies[0];
  // The judge's ends never block: every read and write waits in poll() for its deadline first.
  ::fcntl(request_fd_, F_SETFL, ::fcntl(request_fd_, F_GETFL) | O_NONBLOCK);
  ::fcntl(reply_fd_, F_SETFL, ::fcntl(reply_fd_, F_GETFL) | O_NONBLOCK);
}

namespace {
// Waits until `fd` is ready for `events` or is closed (true), or the deadline passes (false).
bool wait_ready(int fd, short events, Clock::time_point deadline) {
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd ready_fd{fd, events, 0};
    const int ready = ::poll(&ready_fd, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready > 0) return true;
    if (ready < 0 && errno != EINTR) return true;  // let the read or write report it
  }
}
}  // namespace

bool StageProcess::send(const std::string& payload, Clock::time_point deadline) {
  return protocol::write_frame(request_fd_, payload, [&]() { return wait_ready(request_fd_, POLLOUT, deadline); });
}

protocol::FrameRead StageProcess::receive(std::string& payload, std::uint32_t max_bytes, Clock::time_point deadline) {
  return protocol::read_frame(reply_fd_, payload, max_bytes, [&]() { return wait_for_reply(deadline); });
}

bool StageProcess::wait_for_reply(Clock::time_point deadline) const { return wait_ready(reply_fd_, POLLIN, deadline); }

ProcessEnd StageProcess::stop(bool kill_now, std::string& output) {
  ProcessEnd end;
  if (!child_) return end;
  const pid_t pid = child_->pid;
  ::close(request_fd_);  // a server waiting for requests sees end of file and exits
  int status = 0;
  bool done = false;
  if (!kill_now)
    for (int i = 0; i < 500 && !done; ++i) {
      done = ::waitpid(pid, &status, WNOHANG) == pid;
      if (!done) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  if (!done) {
    ::kill(pid, SIGKILL);  // with a PID namespace, its process 1: the kernel kills all of it
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
  }
  if (child_->end_report_fd >= 0) {  // the server's own end, if it ended before its process 1
    int server_status = 0;
    ::fcntl(child_->end_report_fd, F_SETFL, ::fcntl(child_->end_report_fd, F_GETFL) | O_NONBLOCK);
    if (::read(child_->end_report_fd, &server_status, sizeof server_status) == sizeof server_status) status = server_status;
    ::close(child_->end_report_fd);
  }
  if (WIFSIGNALED(status)) {
    end.crashed = true;
    end.crash = signal_description(WTERMSIG(status));
  } else if (WIFEXITED(status)) {
    end.exit_code = WEXITSTATUS(status);
  }
  kill_every_descendant();
  if (child_->cgroup && child_->cgroup->killed_for_memory()) {
    end.crashed = true;
    end.crash = {MessageId::crash_memory_limit, {{"limit", std::to_string(child_->memory_limit_mb)}}};
  }
  child_->cgroup.reset();  // (its folders removed: every process of the stage has ended)
  ::close(reply_fd_);
  // What the stage code printed (the memfd is ours alone now).
  std::string text(static_cast<std::size_t>(child_->output_limit_bytes), '\0');
  const ssize_t got = ::pread(child_->output_fd, text.data(), text.size(), 0);
  if (got > 0) output.append(text.data(), static_cast<std::size_t>(got));
  ::close(child_->output_fd);
  child_.reset();
  request_fd_ = reply_fd_ = -1;
  return end;
}

}  // namespace raylab::grading
