#include "stage_session.h"

#include "bvh_violation_text.h"
#include "grading.h"

#include "raylab/error.h"
#include "raylab/stage_table.h"

#include <cstring>
#include <sstream>
#include <system_error>

namespace raylab::grading {

using protocol::Reader;
using protocol::Writer;

StageSession& StageSession::instance() {
  static StageSession session;
  return session;
}

void StageSession::begin_stage() {
  used_seconds_ = 0;
  losses_ = 0;
  test_.clear();
  test_loss_.reset();
  abandoned_.reset();
  problem_.reset();
  output_.clear();
}

void StageSession::begin_test(const std::string& test) {
  test_ = test;
  test_loss_.reset();
}

std::optional<Message> StageSession::test_loss() const { return test_loss_; }

StageEnd StageSession::end_stage() {
  if (process_.running()) process_.stop(false, output_);
  return {problem_, output_};
}

Message StageSession::where() const {
  if (test_.empty()) return MessageId::lost_before_first_test;
  return {MessageId::lost_in_test, {{"test", test_}}};
}

StageSession::DiagnosticCalls::DiagnosticCalls(double seconds)
    : previous_(StageSession::instance().diagnostic_seconds_) {
  StageSession::instance().diagnostic_seconds_ = seconds;
}
StageSession::DiagnosticCalls::~DiagnosticCalls() { StageSession::instance().diagnostic_seconds_ = previous_; }

void StageSession::lose(const Message& reason, bool timed_out) {
  // A diagnostic call's loss: the server is stopped already (every path here stops it first).
  if (diagnostic_seconds_) throw StageLost(render(reason, Language::English));
  if (!problem_) problem_ = Message{MessageId::lost_problem, {{"reason", reason}, {"where", where()}}};
  test_loss_ = Message{MessageId::lost_during_this_test, {{"reason", reason}}};
  ++losses_;
  if (timed_out)
    abandoned_ = Message{MessageId::lost_not_run, {{"reason", reason}, {"where", where()}}};
  else if (losses_ > options_.max_restarts)
    abandoned_ = Message{MessageId::lost_not_run_after_failures,
                         {{"count", std::to_string(losses_)}, {"reason", reason}, {"where", where()}}};
  throw StageLost(render(reason, Language::English));
}

Message StageSession::during(const StageCall& stage_call) {
  return stage_call.during == MessageId::lost_during_function
             ? Message{MessageId::lost_during_function, {{"function", stage_call.description}}}
             : Message(stage_call.during);
}

void StageSession::reject_reply(const StageCall& stage_call, const Message& what) {
  if (process_.running()) process_.stop(true, output_);
  // A reply too large for its call: a result that grew without end (a tree of far too many nodes),
  // or stray bytes read as a frame's length. Said as either.
  const MessageId reason = what.id == MessageId::protocol_frame_too_large ? MessageId::lost_answer_too_large
                                                                          : MessageId::lost_malformed_answer;
  lose({reason, {{"during", during(stage_call)}, {"what", what}}}, false);
}

std::string StageSession::call(const StageCall& stage_call, const Writer& arguments, std::uint32_t max_reply_bytes,
                               const Callback& on_callback) {
  if (abandoned_) {
    test_loss_ = abandoned_;
    throw StageLost(render(*abandoned_, Language::English));
  }
  if (test_loss_) throw StageLost(render(*test_loss_, Language::English));
  const auto started = Clock::now();
  auto deadline = started + std::chrono::duration_cast<Clock::duration>(
                                std::chrono::duration<double>(options_.stage_seconds - used_seconds_));
  if (options_.run_deadline < deadline) deadline = options_.run_deadline;
  if (diagnostic_seconds_) {
    const auto diagnostic_deadline =
        started + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(*diagnostic_seconds_));
    if (diagnostic_deadline < deadline) deadline = diagnostic_deadline;
  }
  struct Account {  // the call's time counts against the stage, however it ends
    StageSession& session;
    Clock::time_point started;
    ~Account() { session.used_seconds_ += std::chrono::duration<double>(Clock::now() - started).count(); }
  } account{*this, started};

  auto timed_out = [&]() {
    process_.stop(true, output_);
    if (deadline == options_.run_deadline) lose(MessageId::lost_run_time_limit, true);
    lose({MessageId::lost_timed_out, {{"seconds", stream_text(options_.stage_seconds)}}}, true);
  };
  auto ended = [&]() {
    const ProcessEnd end = process_.stop(false, output_);
    if (end.crashed) lose({MessageId::lost_crashed, {{"crash", end.crash}}}, false);
    lose({MessageId::lost_exited, {{"status", std::to_string(end.exit_code)}, {"during", during(stage_call)}}}, false);
  };
  auto garbled = [&](const Message& what) { reject_reply(stage_call, what); };
  // Sends a frame within the deadline; a server that is gone ends the call.
  auto send = [&](const std::string& payload) {
    bool sent = false;
    try {
      sent = process_.send(payload, deadline);
    } catch (const std::system_error&) {
      ended();  // EPIPE: it is gone
    }
    if (!sent) timed_out();  // it stopped reading its requests
  };

  if (!process_.running()) {
    try {
      process_.start(options_.server_path, options_.limits);
    } catch (const std::exception& e) {
      lose({MessageId::lost_not_started, {{"error", e.what()}}}, false);
    }
    ++generation_;
  }
  Writer request;
  request.put(protocol::kCall);
  request.put_string(stage_call.name);
  request.bytes() += arguments.bytes();
  send(request.bytes());
  for (;;) {
    std::string reply;
    try {
      const protocol::FrameRead read = process_.receive(reply, max_reply_bytes, deadline);
      if (read == protocol::FrameRead::kTimedOut) timed_out();
      if (read == protocol::FrameRead::kEnd) ended();
    } catch (const protocol::ProtocolError& e) {
      garbled(e.problem);
    } catch (const std::system_error&) {
      ended();
    }
    if (reply.empty()) garbled(MessageId::protocol_empty_frame);
    const auto kind = static_cast<std::uint8_t>(reply[0]);
    if (kind == protocol::kReturn) return reply;
    if (kind == protocol::kCallback && on_callback) {
      if (reply.size() > protocol::kMaxCallbackBytes)
        garbled({MessageId::protocol_frame_too_large, {{"bytes", std::to_string(reply.size())}}});
      Writer answer;
      answer.put(protocol::kReturn);
      try {
        Reader in(reply);
        in.get<std::uint8_t>();
        on_callback(in, answer);
      } catch (const protocol::ProtocolError& e) {
        garbled(e.problem);
      } catch (...) {
        // The judge's own callback gave up (say, the traversal did too much work): the server
        // is stuck in the call, so it goes, but the stage code did nothing wrong.
        process_.stop(true, output_);
        throw;
      }
      send(answer.bytes());
      continue;
    }
    if (kind != protocol::kThrow) garbled(MessageId::protocol_unknown_frame);
    std::string message, stage_id, function_text;
    protocol::ExceptionKind exception{};
    bool names_a_mesh = false;
    BvhViolation broken_rule;
    std::uint64_t boxes = 0;
    try {
      Reader in(reply);
      in.get<std::uint8_t>();
      exception = in.get<protocol::ExceptionKind>();
      message = protocol::cut_text(in.get_string(), protocol::kMaxExceptionTextBytes);
      stage_id = protocol::cut_text(in.get_string(), protocol::kMaxExceptionTextBytes);
      function_text = protocol::cut_text(in.get_string(), protocol::kMaxExceptionTextBytes);
      if (exception == protocol::ExceptionKind::BrokenTree) {
        names_a_mesh = in.get<std::uint8_t>() != 0;
        broken_rule = in.get<BvhViolation>();
        boxes = in.get<std::uint64_t>();
      }
      in.expect_end();
    } catch (const protocol::ProtocolError& e) {
      garbled(e.problem);
    }
    if (exception == protocol::ExceptionKind::NotImplemented) {
      // Rebuild the stub's exception from the stage table (its message names the file to write).
      if (stage_of_function(function_text)) {
        const NotImplemented stub(function_text);
        (void)exception_text(not_implemented_message(stub));  // shown in the run's language
        throw stub;
      }
      throw std::runtime_error(message);
    }
    if (exception == protocol::ExceptionKind::BrokenTree) {
      const std::optional<std::string> mesh = names_a_mesh ? std::optional<std::string>(message) : std::nullopt;
      throw std::runtime_error(exception_text(broken_tree_message(broken_rule, boxes, mesh)));
    }
    if (exception == protocol::ExceptionKind::OutOfMemory)
      throw std::runtime_error(exception_text(MessageId::stage_out_of_memory));
    if (exception == protocol::ExceptionKind::InvalidArgument) throw std::invalid_argument(message);
    throw std::runtime_error(message);
  }
}

}  // namespace raylab::grading
