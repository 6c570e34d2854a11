// The stage server: the one program that links stage code (the student's, or a self-test
// submission's). The judge starts it, sandboxed (stage_process.h), sends it one request at a time on
// descriptor 3 (protocol.h) and reads each answer on descriptor 4. It decides nothing: it
// returns what the stage functions return, and the judge grades that.
#include "protocol.h"
#include "stage_call.h"

#include "raylab/bvh_tools.h"
#include "raylab/error.h"

#include <exception>
#include <new>
#include <iostream>

namespace {

using namespace raylab;
using namespace raylab::grading;
using namespace raylab::grading::protocol;

// A request: the call's name, then its arguments, which its handler reads (stage_call.h).
void answer(Reader& in, Writer& out) {
  const std::string name = in.get_string();
  const Handler handler = find_handler(name);
  if (!handler) throw ProtocolError(MessageId::protocol_unknown_request);
  handler(in, out);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    adopt_channels(argc, argv);
  } catch (const ProtocolError& e) {
    std::cerr << "stage server: " << render(e.problem) << "\n";  // run by hand: in the language of LANG
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "stage server: " << e.what() << "\n";
    return 2;
  }
  std::string request;
  for (;;) {
    try {
      if (!read_frame(kRequestFd, request)) return 0;  // the judge is done with this process
    } catch (const std::exception& e) {
      std::cerr << "stage server: " << e.what() << "\n";
      return 0;
    }
    Writer out;
    out.put(kReturn);
    try {
      Reader in(request);
      if (in.get<std::uint8_t>() != kCall) throw ProtocolError(MessageId::protocol_expected_call);
      answer(in, out);
    } catch (const NotImplemented& e) {
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::NotImplemented);
      out.put_string(e.what());
      out.put_string(e.stage_id());
      out.put_string(e.function());
    } catch (const BrokenBvh& e) {  // the judge words it (stage_broken_tree)
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::BrokenTree);
      out.put_string(e.mesh.value_or(""));
      out.put_string("");
      out.put_string("");
      out.put(std::uint8_t(e.mesh.has_value()));
      out.put(e.violation);
      out.put(e.boxes);
    } catch (const std::bad_alloc&) {
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::OutOfMemory);  // the judge words it (stage_out_of_memory)
      out.put_string("");
      out.put_string("");
      out.put_string("");
    } catch (const std::invalid_argument& e) {
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::InvalidArgument);
      out.put_string(cut_text(e.what(), kMaxExceptionTextBytes));
      out.put_string("");
      out.put_string("");
    } catch (const std::exception& e) {
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::Other);
      out.put_string(cut_text(e.what(), kMaxExceptionTextBytes));
      out.put_string("");
      out.put_string("");
    } catch (...) {
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::Other);
      out.put_string("an exception that is not a std::exception");
      out.put_string("");
      out.put_string("");
    }
    write_frame(kReplyFd, out.bytes());
  }
}
