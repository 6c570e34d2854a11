// autograder-confine: runs a command that may read only beneath the paths it is given and write
// only beneath others (Landlock, runner/landlock.h). tools/autograder-batch compiles each
// student's stage files through it, so that no #include, .incbin or other trick in a student's
// source can read solutions/, the course's seed or the private cases: only the system, the kit's
// include folders and the student's own files.
//
//   autograder-confine [--read PATH]... [--write PATH]... -- COMMAND [ARGUMENTS...]
//   autograder-confine --check
//
// A path is a folder (everything beneath it) or a file. Reading includes running programs.
// Exit status: COMMAND's own (it replaces this process); 125 when it cannot confine (no Landlock
// on this kernel, a path that cannot be opened); 127 when COMMAND cannot be run. --check exits 0
// when this kernel can confine, else 125 with the reason.
#include "landlock.h"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace landlock = raylab::grading::landlock;

namespace {

[[noreturn]] void cannot_confine(const std::string& why) {
  std::fprintf(stderr, "autograder-confine: %s\n", why.c_str());
  std::exit(125);
}

// Grants `rights` beneath `path` (a file gets the rights that apply to files).
void grant(int ruleset, const std::string& path, std::uint64_t rights) {
  const int fd = ::open(path.c_str(), O_PATH | O_CLOEXEC);
  if (fd < 0) cannot_confine(path + ": " + std::strerror(errno));
  struct stat status {};
  if (::fstat(fd, &status) != 0) cannot_confine(path + ": " + std::strerror(errno));
  if (!S_ISDIR(status.st_mode)) rights &= landlock::kFileAccess;
  if (!landlock::add_path_rule(ruleset, fd, rights)) cannot_confine(path + ": landlock_add_rule: " + std::strerror(errno));
  ::close(fd);
}

}  // namespace

int main(int argc, char** argv) {
  // Everything after "--" is the command, whatever it looks like.
  const auto separator = std::find_if(argv + 1, argv + argc, [](const char* a) { return std::strcmp(a, "--") == 0; });
  std::vector<std::string> readable, writable;
  bool check = false;
  CLI::App app{"Runs COMMAND able to read only beneath the --read paths and to write only beneath the --write paths "
               "(Landlock): autograder-confine [--read PATH]... [--write PATH]... -- COMMAND [ARGUMENTS...]"};
  app.add_option("--read", readable, "A folder or file COMMAND may read (and run)");
  app.add_option("--write", writable, "A folder or file COMMAND may read and write");
  app.add_flag("--check", check, "Only say whether this kernel can confine (exit 0) or not (exit 125)");
  CLI11_PARSE(app, static_cast<int>(separator - argv), argv);

  const int version = landlock::abi();
  if (version == 0)
    cannot_confine("this kernel has no Landlock (Linux 5.13 or later, with landlock in its lsm= list): "
                   "a command cannot be kept from reading any file its user can read");
  if (check) return 0;
  if (separator == argv + argc || separator + 1 == argv + argc)
    cannot_confine("no command: autograder-confine [--read PATH]... [--write PATH]... -- COMMAND [ARGUMENTS...]");

  const std::uint64_t handled = landlock::file_accesses(version);
  const int ruleset = landlock::create_ruleset({handled, 0, 0}, version);
  if (ruleset < 0) cannot_confine(std::string("landlock_create_ruleset: ") + std::strerror(errno));
  for (const std::string& path : readable) grant(ruleset, path, landlock::kReadAccess);
  for (const std::string& path : writable) grant(ruleset, path, handled);
  if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) cannot_confine(std::string("no_new_privs: ") + std::strerror(errno));
  if (!landlock::restrict_self(ruleset)) cannot_confine(std::string("landlock_restrict_self: ") + std::strerror(errno));
  ::close(ruleset);
  ::execvp(separator[1], separator + 1);
  std::fprintf(stderr, "autograder-confine: cannot run %s: %s\n", separator[1], std::strerror(errno));
  return 127;
}
