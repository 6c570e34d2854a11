// The judge's side of one stage: a stage server (stage_process.h) per stretch of calls, the stage's
// time budget, and the resume policy.
//
// Resume policy: every call of a stage function goes to the current stage server. If that server
// crashes, exits (even with status 0), sends garbage or stops answering, the call throws
// StageLost, the rest of the test is lost with the reason, and the next test starts a fresh
// server. The stage's time (all its calls together, server start-ups included) and the whole
// run's time are limited: after a time-out, or after too many lost servers, the stage's
// remaining tests are lost without running stage code.
#pragma once

#include "stage_process.h"
#include "protocol.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace raylab::grading {

// One kind of request to the stage server: a stage function, or a batch of calls of one. Each
// stage's calls file defines its own (stage_call.h).
struct StageCall {
  const char* name;         // what the request carries; unique among all stages' calls
  const char* description;  // what the judge's messages name: "... during <description>"
  // The words for "... during <description>" in either language: lost_during_function with the
  // description (a function named in code, the same in both), or an entry of its own.
  MessageId during = MessageId::lost_during_function;
};

// A call into stage code that delivered no result: the process died, timed out or misbehaved.
struct StageLost : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SessionOptions {
  std::string server_path;     // the stage server linked with the graded code
  SandboxLimits limits;
  double stage_seconds = 60;   // per stage, all its calls together
  Clock::time_point run_deadline = Clock::time_point::max();
  int max_restarts = 3;        // fresh servers after a loss, per stage
};

struct StageEnd {
  std::optional<Message> problem;  // the first loss, for the score table
  std::string output;              // what the stage code printed
};

class StageSession {
 public:
  static StageSession& instance();

  void configure(const SessionOptions& options) { options_ = options; }
  // The stage server of the next stage (its first call starts it; end_stage stopped the last).
  void set_server_path(const std::string& path) { options_.server_path = path; }
  const SessionOptions& options() const { return options_; }

  void begin_stage();
  // test: "Suite.Name", or "" for the stage's probe before its tests.
  void begin_test(const std::string& test);
  // The reason the current test lost its stage calls, if it did (messages.def: lost_...).
  std::optional<Message> test_loss() const;
  // Stops the stage's server and every process it started; only then is anything reported.
  StageEnd end_stage();

  // One request (stage_call.h: remote() sends it and reads the reply); returns the payload of
  // the kReturn reply (its first byte is the kind). Stage exceptions are rethrown here
  // (NotImplemented, std::invalid_argument, std::runtime_error); on_callback answers the
  // server's questions during the call (kCallback frames: stage_call.h, ask_judge).
  // Every read and write of the call waits for the stage's deadline at most, and the reply may be
  // max_reply_bytes long at most (stage_call.h: remote() says how much each call may return).
  using Callback = std::function<void(protocol::Reader& request, protocol::Writer& answer)>;
  std::string call(const StageCall& stage_call, const protocol::Writer& arguments, std::uint32_t max_reply_bytes,
                   const Callback& on_callback = {});
  // A reply that call() returned but whose contents are malformed (a list of the wrong length, a
  // size that does not match): the server goes, and the test is lost with the reason, as for a
  // malformed frame. Throws StageLost.
  [[noreturn]] void reject_reply(const StageCall& stage_call, const Message& what);

  // While it lives, this thread's calls are diagnostic (a failing picture's traced pixel, which
  // is only shown): each waits `seconds` at most (and no longer than the stage's deadline), and
  // one that is lost stops the server as any lost call does (the next call starts a fresh one)
  // but costs nothing else: the test, the stage's restarts and its problem are as if it had not
  // been made. The call still throws StageLost, for the caller to go on without its answer.
  class DiagnosticCalls {
   public:
    explicit DiagnosticCalls(double seconds);
    ~DiagnosticCalls();
    DiagnosticCalls(const DiagnosticCalls&) = delete;
    DiagnosticCalls& operator=(const DiagnosticCalls&) = delete;

   private:
    std::optional<double> previous_;
  };

  // Increases whenever a fresh server starts (what it was sent before is gone).
  unsigned server_generation() const { return generation_; }
  bool server_running() const { return process_.running(); }

 private:
  // Ends the call: the test (and after a time-out or too many losses, the stage) is lost. `reason`
  // says what the process did, a lost_... message ("timed out after 60 s (an endless loop?)").
  [[noreturn]] void lose(const Message& reason, bool timed_out);
  Message where() const;
  static Message during(const StageCall& stage_call);

  SessionOptions options_;
  StageProcess process_;
  unsigned generation_ = 0;
  double used_seconds_ = 0;
  int losses_ = 0;
  std::string test_, output_;
  std::optional<Message> test_loss_, abandoned_, problem_;
  std::optional<double> diagnostic_seconds_;  // DiagnosticCalls
};

}  // namespace raylab::grading
