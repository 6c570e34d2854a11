#include "stage_session.h"

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
  test_loss_.clear();
  abandoned_.clear();
  problem_.clear();
  output_.clear();
}

void StageSession::begin_test(const std::string& test) {
  test_ = test;
  test_loss_.clear();
}

std::optional<std::string> StageSession::test_loss() const {
  if (!test_loss_.empty()) return test_loss_;
  return std::nullopt;
}

StageEnd StageSession::end_stage() {
  if (process_.running()) process_.stop(false, output_);
  return {problem_, output_};
}

std::string StageSession::where() const { return test_.empty() ? "before its first test" : "in " + test_; }

void StageSession::lose(const std::string& reason, bool timed_out) {
  if (problem_.empty()) problem_ = reason + ", " + where();
  test_loss_ = reason + " during this test";
  ++losses_;
  if (timed_out)
    abandoned_ = "not run: the stage's process " + reason + " " + where();
  else if (losses_ > options_.max_restarts)
    abandoned_ = "not run: the stage's process failed " + std::to_string(losses_) + " times; the last time it " + reason + " " + where();
  throw StageLost(reason);
}

std::string StageSession::call(const StageCall& stage_call, const Writer& arguments, const Callback& on_callback) {
  if (!abandoned_.empty()) {
    test_loss_ = abandoned_;
    throw StageLost(abandoned_);
  }
  if (!test_loss_.empty()) throw StageLost(test_loss_);
  const auto started = Clock::now();
  auto deadline = started + std::chrono::duration_cast<Clock::duration>(
                                std::chrono::duration<double>(options_.stage_seconds - used_seconds_));
  if (options_.run_deadline < deadline) deadline = options_.run_deadline;
  struct Account {  // the call's time counts against the stage, however it ends
    StageSession& session;
    Clock::time_point started;
    ~Account() { session.used_seconds_ += std::chrono::duration<double>(Clock::now() - started).count(); }
  } account{*this, started};

  const std::string during = std::string(" during ") + stage_call.description;
  auto timed_out = [&]() {
    process_.stop(true, output_);
    std::ostringstream text;
    if (deadline == options_.run_deadline) text << "ran past the time limit of the whole grading run";
    else text << "timed out after " << options_.stage_seconds << " s (an endless loop?)";
    lose(text.str(), true);
  };
  auto ended = [&]() {
    const ProcessEnd end = process_.stop(false, output_);
    if (end.crashed) lose("crashed with " + end.crash, false);
    lose("exited (status " + std::to_string(end.exit_code) + ")" + during + ": do not call exit() in stage code", false);
  };
  auto garbled = [&](const std::string& what) {
    process_.stop(true, output_);
    lose("sent the grader a malformed answer" + during + " (" + what +
             "): stage code must not write to descriptors it did not open",
         false);
  };

  if (!process_.running()) {
    try {
      process_.start(options_.server_path, options_.limits);
    } catch (const std::exception& e) {
      lose(std::string("could not be started: ") + e.what(), false);
    }
    ++generation_;
  }
  Writer request;
  request.put(protocol::kCall);
  request.put_string(stage_call.name);
  request.bytes() += arguments.bytes();
  try {
    protocol::write_frame(process_.request_fd(), request.bytes());
  } catch (const std::system_error&) {
    ended();  // EPIPE: it is gone
  }
  for (;;) {
    if (!process_.wait_for_reply(deadline)) timed_out();
    std::string reply;
    try {
      if (!protocol::read_frame(process_.reply_fd(), reply)) ended();
    } catch (const protocol::ProtocolError& e) {
      garbled(e.what());
    } catch (const std::system_error&) {
      ended();
    }
    if (reply.empty()) garbled("an empty frame");
    const auto kind = static_cast<std::uint8_t>(reply[0]);
    if (kind == protocol::kReturn) return reply;
    if (kind == protocol::kCallback && on_callback) {
      Writer answer;
      answer.put(protocol::kReturn);
      try {
        Reader in(reply);
        in.get<std::uint8_t>();
        on_callback(in, answer);
      } catch (const protocol::ProtocolError& e) {
        garbled(e.what());
      } catch (...) {
        // The judge's own callback gave up (say, the traversal did too much work): the server
        // is stuck in the call, so it goes, but the stage code did nothing wrong.
        process_.stop(true, output_);
        throw;
      }
      try {
        protocol::write_frame(process_.request_fd(), answer.bytes());
      } catch (const std::system_error&) {
        ended();
      }
      continue;
    }
    if (kind != protocol::kThrow) garbled("an unknown kind of frame");
    std::string message, stage_id, function_text;
    protocol::ExceptionKind exception{};
    try {
      Reader in(reply);
      in.get<std::uint8_t>();
      exception = in.get<protocol::ExceptionKind>();
      message = in.get_string();
      stage_id = in.get_string();
      function_text = in.get_string();
      in.expect_end();
    } catch (const protocol::ProtocolError& e) {
      garbled(e.what());
    }
    if (exception == protocol::ExceptionKind::NotImplemented) {
      // Rebuild the stub's exception from the stage table (its message names the file to write).
      if (stage_of_function(function_text)) throw NotImplemented(function_text);
      throw std::runtime_error(message);
    }
    if (exception == protocol::ExceptionKind::InvalidArgument) throw std::invalid_argument(message);
    throw std::runtime_error(message);
  }
}

}  // namespace raylab::grading
