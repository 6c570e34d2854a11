// A stage server that misbehaves on purpose, for test_stage_process.cpp: what a stage's code can do
// to the judge through the pipes it inherits (descriptors 3 and 4), chosen by the first letter of
// the environment variable RAYLAB_TEST_SERVER:
//   echo      answers each request with its own bytes (the judge's side works at all)
//   partial   reads the request, sends a frame's header and part of its payload, and waits
//   unread    never reads its requests
//   huge      reads the request and announces a 256 MiB frame
//   flood     reads the request, then asks the judge questions (kCallback frames) without end and
//             never reads the answers
//   hoard     (Linux) reads the request, fills 55 memfds with 1 MiB each (memory that its address
//             space does not count), answers, and waits
#include "protocol.h"

#ifdef __linux__
#include <sys/mman.h>
#endif
#include <unistd.h>

#include <cstdlib>
#include <string>

using namespace raylab::grading::protocol;

int main() {
  const char* mode_text = std::getenv("RAYLAB_TEST_SERVER");
  const std::string mode = mode_text ? mode_text : "";
  std::string request;
  if (mode == "unread") {
    for (;;) ::pause();
  }
  if (!read_frame(kRequestFd, request)) return 0;
  if (mode == "echo") {
    for (;;) {
      write_frame(kReplyFd, request);
      if (!read_frame(kRequestFd, request)) return 0;
    }
  }
  if (mode == "partial") {
    const unsigned char part[] = {100, 0, 0, 0, kReturn, 1, 2, 3};
    if (::write(kReplyFd, part, sizeof part) != static_cast<ssize_t>(sizeof part)) return 1;
    for (;;) ::pause();
  }
  if (mode == "huge") {
    const unsigned char header[] = {0, 0, 0, 16, kReturn};
    if (::write(kReplyFd, header, sizeof header) != static_cast<ssize_t>(sizeof header)) return 1;
    for (;;) ::pause();
  }
#ifdef __linux__
  if (mode == "hoard") {
    const std::string mebibyte(1u << 20, 'x');
    for (int file = 0; file < 55; ++file) {
      const int fd = ::memfd_create("hoard", 0);
      if (fd < 0 || ::write(fd, mebibyte.data(), mebibyte.size()) != static_cast<ssize_t>(mebibyte.size())) return 3;
    }
    write_frame(kReplyFd, request);
    for (;;) ::pause();
  }
#endif
  if (mode == "flood") {
    const std::string question = std::string(1, static_cast<char>(kCallback)) + "question";
    for (;;) write_frame(kReplyFd, question);
  }
  return 2;
}
