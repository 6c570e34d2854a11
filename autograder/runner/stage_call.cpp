// The stage server's side of stage_call.h: the handlers the stages' calls files registered, and
// the channel back to the judge during a call.
#include "stage_call.h"

#include <cstdlib>
#include <map>
#include <stdexcept>

namespace raylab::grading {
namespace {

std::map<std::string, Handler>& handlers() {
  static std::map<std::string, Handler> registered;
  return registered;
}

// The handler of call_remote_each: the named call's handler once per set of arguments.
void serve_each(protocol::Reader& in, protocol::Writer& out) {
  const Handler handler = find_handler(in.get_string());
  if (!handler || handler == &serve_each) throw protocol::ProtocolError(MessageId::protocol_unknown_request);
  const auto count = in.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < count; ++i) handler(in, out);
}

}  // namespace

bool serve(const StageCall& call, Handler handler) {
  if (!handlers().emplace(call.name, handler).second)
    throw std::logic_error(std::string("two stage calls are named ") + call.name + " (autograder/suites/*_calls.cpp)");
  return true;
}

Handler find_handler(const std::string& name) {
  const auto found = handlers().find(name);
  return found == handlers().end() ? nullptr : found->second;
}

std::string ask_judge(const protocol::Writer& question) {
  protocol::Writer frame;
  frame.put(protocol::kCallback);
  frame.bytes() += question.bytes();
  protocol::write_frame(protocol::kReplyFd, frame.bytes());
  std::string answer;
  if (!protocol::read_frame(protocol::kRequestFd, answer)) std::exit(0);  // the judge went away
  if (answer.empty() || static_cast<std::uint8_t>(answer[0]) != protocol::kReturn)
    throw protocol::ProtocolError(MessageId::protocol_expected_answer);
  return answer.substr(1);
}

namespace {
const bool kEachServed = serve(kEachCall, serve_each);
}  // namespace

}  // namespace raylab::grading
