// Landlock (Linux 5.13 and later; linux/landlock.h of newer kernels, spelled out for older
// headers): a process restricts itself, and everything it starts, to the accesses it grants.
// Used by the stage server's sandbox (process_linux.cpp: no writes, no TCP, no signals out) and
// by autograder-confine (tools/confine.cpp: a student's compile reads only what it is given).
// Header-only, system calls only: the sandbox applies it between fork and exec.
#pragma once

#include <sys/syscall.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>

namespace raylab::grading::landlock {

struct RulesetAttr {
  std::uint64_t handled_access_fs;
  std::uint64_t handled_access_net;
  std::uint64_t scoped;
};

// File accesses (LANDLOCK_ACCESS_FS_...), by the ABI that added them.
constexpr std::uint64_t kExecute = 1ull << 0, kWriteFile = 1ull << 1, kReadFile = 1ull << 2, kReadDir = 1ull << 3;
constexpr std::uint64_t kWriteAccess =
    kWriteFile | (1ull << 4)  // REMOVE_DIR
    | (1ull << 5)             // REMOVE_FILE
    | (1ull << 6)             // MAKE_CHAR
    | (1ull << 7)             // MAKE_DIR
    | (1ull << 8)             // MAKE_REG
    | (1ull << 9)             // MAKE_SOCK
    | (1ull << 10)            // MAKE_FIFO
    | (1ull << 11)            // MAKE_BLOCK
    | (1ull << 12);           // MAKE_SYM
constexpr std::uint64_t kReadAccess = kExecute | kReadFile | kReadDir;
constexpr std::uint64_t kReferAccess = 1ull << 13;     // ABI 2
constexpr std::uint64_t kTruncateAccess = 1ull << 14;  // ABI 3
constexpr std::uint64_t kIoctlDevAccess = 1ull << 15;  // ABI 5
// The rights that apply to a file (the others apply to folders only).
constexpr std::uint64_t kFileAccess = kExecute | kWriteFile | kReadFile | kTruncateAccess | kIoctlDevAccess;
// TCP (ABI 4): BIND_TCP, CONNECT_TCP. Scopes (ABI 6): abstract unix sockets, signals.
constexpr std::uint64_t kNetAccess = (1ull << 0) | (1ull << 1);
constexpr std::uint64_t kScopes = (1ull << 0) | (1ull << 1);

// The kernel's Landlock ABI version, 0 when it has none (or it is turned off).
inline int abi() {
#ifdef SYS_landlock_create_ruleset
  const long version = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, 1u /* LANDLOCK_CREATE_RULESET_VERSION */);
  return version > 0 ? static_cast<int>(version) : 0;
#else
  return 0;
#endif
}

// Every file access that ABI `version` can restrict.
inline std::uint64_t file_accesses(int version) {
  std::uint64_t accesses = kReadAccess | kWriteAccess;
  if (version >= 2) accesses |= kReferAccess;
  if (version >= 3) accesses |= kTruncateAccess;
  if (version >= 5) accesses |= kIoctlDevAccess;
  return accesses;
}

// A ruleset handling `attr` (its size by the ABI: scopes from 6, network from 4), or -1.
inline int create_ruleset(const RulesetAttr& attr, int version) {
#ifdef SYS_landlock_create_ruleset
  const std::size_t size = version >= 6 ? sizeof(RulesetAttr) : version >= 4 ? 2 * sizeof(std::uint64_t) : sizeof(std::uint64_t);
  return static_cast<int>(::syscall(SYS_landlock_create_ruleset, &attr, size, 0u));
#else
  (void)attr;
  (void)version;
  return -1;
#endif
}

// Grants `allowed` beneath the folder (or on the file) open as `path_fd` (O_PATH). False on error.
inline bool add_path_rule(int ruleset, int path_fd, std::uint64_t allowed) {
#ifdef SYS_landlock_add_rule
  struct __attribute__((packed)) {
    std::uint64_t allowed_access;
    std::int32_t parent_fd;
  } rule{allowed, path_fd};
  return ::syscall(SYS_landlock_add_rule, ruleset, 1 /* LANDLOCK_RULE_PATH_BENEATH */, &rule, 0u) == 0;
#else
  (void)ruleset;
  (void)path_fd;
  (void)allowed;
  return false;
#endif
}

// Restricts this process (PR_SET_NO_NEW_PRIVS must be set) to the ruleset. False on error.
inline bool restrict_self(int ruleset) {
#ifdef SYS_landlock_restrict_self
  return ::syscall(SYS_landlock_restrict_self, ruleset, 0u) == 0;
#else
  (void)ruleset;
  return false;
#endif
}

}  // namespace raylab::grading::landlock
