// Process control for the judge: starting a sandboxed stage server, waiting for its answers
// with a deadline, and making sure that it and everything it started are gone. The only
// platform-specific part of the autograder (named stage_process.h, not process.h, which
// MinGW's pthread.h includes): one file per platform implements this header,
// process_linux.cpp (fork, rlimits, Landlock, a private uid) and process_windows.cpp (a job
// object); the judge, the stage server and the protocol are the same on both.
#pragma once

#include "messages.h"
#include "protocol.h"

#include <chrono>
#include <memory>
#include <string>

namespace raylab::grading {

using Clock = std::chrono::steady_clock;

struct SandboxLimits {
  long memory_limit_mb = 4096;        // Linux: address space of the stage server; Windows: memory
                                      // committed by all its processes together (0: none)
  long output_limit_bytes = 1 << 20;  // stdout + stderr the stage code may write
  int max_processes = 32;             // processes the stage code may have at once
};

// How a stage server ended.
struct ProcessEnd {
  bool crashed = false;  // killed by a signal (Linux) or ended by an exception (Windows)
  Message crash{MessageId::crash_killed};  // then: what it was, named for a student ("signal 11
                         // (Segmentation fault): your code read or wrote memory it does not own ...")
  int exit_code = 0;     // else: its exit status
};

// Once, before the first stage server: on Linux makes the judge the reaper of every orphan its
// stage servers leave behind and ignores SIGPIPE; on Windows turns off the crash dialogs. Picks
// the sandbox (see sandbox_description).
void prepare_judge();

// The judge's own memory: a limit of `megabytes` (0: none) on this process alone, so a stage server
// may still be given more (Linux: RLIMIT_AS, its soft limit; Windows: the committed memory of a job
// object of its own, which stage servers break away from). Reaching it stops the run
// (autograder_main.cpp: judge_out_of_memory).
void limit_judge_memory(long megabytes);

// This program's own path with "-stage-server" added (before ".exe" on Windows): where
// raylab_add_autograder builds a judge's stage server.
std::string default_stage_server_path();

// What confines stage code on this machine, in one sentence, for the report (sandbox_ messages).
Message sandbox_description();
// The version (1 or 2) of the cgroups in which the judge gives each stage server a cgroup of its
// own, with its memory and process limits; 0 where it gives none (Windows: a job object instead).
int stage_cgroup_version();

class StageProcess {
 public:
  StageProcess();
  StageProcess(const StageProcess&) = delete;
  StageProcess& operator=(const StageProcess&) = delete;
  ~StageProcess();

  // Starts `program` sandboxed, with the request and reply pipes (protocol.h: the server's
  // descriptors 3 and 4), stdin empty, stdout and stderr into a private, size-limited buffer.
  // Throws on failure.
  void start(const std::string& program, const SandboxLimits& limits);
  bool running() const;

  // One request to the server: false when the deadline passed before the server took all of it
  // (a server that stops reading its requests cannot block the judge). Throws std::system_error
  // when the server is gone.
  bool send(const std::string& payload, Clock::time_point deadline);
  // One reply frame of at most max_bytes: kTimedOut when the deadline passed before all of it came
  // (a partial frame costs the call's time, no more), kEnd when the server closed its end first.
  // Throws protocol::ProtocolError on a frame cut short or over max_bytes (before reading it).
  protocol::FrameRead receive(std::string& payload, std::uint32_t max_bytes, Clock::time_point deadline);

  // Ends the stage server (killing it first when `kill_now`, else giving it a moment to finish
  // exiting), then kills every process it started, detached or not. Returns how the server
  // itself ended; appends what it printed to `output` (at most the output limit).
  ProcessEnd stop(bool kill_now, std::string& output);

 private:
  // Waits until the reply pipe has data or is closed (true), or the deadline passes (false).
  bool wait_for_reply(Clock::time_point deadline) const;

  struct Child;  // the platform's handles on the running server (its process_*.cpp)
  std::unique_ptr<Child> child_;
  int request_fd_ = -1, reply_fd_ = -1;
};

}  // namespace raylab::grading
