// Process control for the judge: starting a sandboxed stage server, waiting for its answers
// with a deadline, and making sure that it and everything it started are gone. The only
// platform-specific part of the autograder (process_linux.cpp; a Windows port adds its own file).
#pragma once

#include <chrono>
#include <string>

namespace raylab::grading {

using Clock = std::chrono::steady_clock;

struct SandboxLimits {
  long memory_limit_mb = 4096;        // address space of the stage server (0: none)
  long output_limit_bytes = 1 << 20;  // stdout + stderr the stage code may write
  int max_processes = 32;             // processes the stage code may have at once
};

// How a stage server ended.
struct ProcessEnd {
  bool signalled = false;
  int signal_number = 0;
  int exit_code = 0;
};

// Once, before the first stage server: makes the judge the reaper of every orphan its stage
// servers leave behind, ignores SIGPIPE, and picks the sandbox (see sandbox_description).
void prepare_judge();

// What confines stage code on this machine, in one sentence, for the report.
std::string sandbox_description();

class StageProcess {
 public:
  StageProcess() = default;
  StageProcess(const StageProcess&) = delete;
  StageProcess& operator=(const StageProcess&) = delete;
  ~StageProcess();

  // Starts `program` sandboxed, with the request and reply pipes on descriptors 3 and 4,
  // stdin /dev/null, stdout and stderr into a private, size-limited buffer. Throws on failure.
  void start(const std::string& program, const SandboxLimits& limits);
  bool running() const { return pid_ > 0; }

  int request_fd() const { return request_fd_; }
  int reply_fd() const { return reply_fd_; }

  // Waits until the reply pipe has data or is closed (true), or the deadline passes (false).
  bool wait_for_reply(Clock::time_point deadline) const;

  // Ends the stage server (killing it first when `kill_now`, else giving it a moment to finish
  // exiting), then kills and reaps every process it started, detached or not. Returns how the
  // server itself ended; appends what it printed to `output` (at most the output limit).
  ProcessEnd stop(bool kill_now, std::string& output);

 private:
  int pid_ = -1;
  int request_fd_ = -1, reply_fd_ = -1, output_fd_ = -1;
  long output_limit_bytes_ = 0;
};

}  // namespace raylab::grading
