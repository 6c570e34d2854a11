#include "protocol.h"

#if defined(_WIN32)
#include <fcntl.h>
#include <io.h>
#else
#include <unistd.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <system_error>
#include <utility>

namespace raylab::grading::protocol {
namespace {

// The C runtime's read and write (POSIX names on Linux, underscored ones on Windows).
#if defined(_WIN32)
long long read_some(int fd, char* data, std::size_t size) {
  return ::_read(fd, data, static_cast<unsigned>(std::min<std::size_t>(size, 1u << 30)));
}
long long write_some(int fd, const char* data, std::size_t size) {
  return ::_write(fd, data, static_cast<unsigned>(std::min<std::size_t>(size, 1u << 30)));
}
#else
long long read_some(int fd, char* data, std::size_t size) { return ::read(fd, data, size); }
long long write_some(int fd, const char* data, std::size_t size) { return ::write(fd, data, size); }
#endif

// Reads exactly `size` bytes; returns how many it got before end of file, or before `wait`
// returned false (then timed_out is set). A non-blocking descriptor's EAGAIN waits again.
std::size_t read_fully(int fd, char* data, std::size_t size, const std::function<bool()>* wait, bool& timed_out) {
  std::size_t done = 0;
  while (done < size) {
    if (wait && !(*wait)()) {
      timed_out = true;
      break;
    }
    const long long n = read_some(fd, data + done, size - done);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK) continue;
      throw std::system_error(errno, std::generic_category(), "read");
    }
    done += static_cast<std::size_t>(n);
  }
  return done;
}

FrameRead read_frame_waiting(int fd, std::string& payload, std::uint32_t max_bytes, const std::function<bool()>* wait) {
  unsigned char header[4];
  bool timed_out = false;
  const std::size_t got = read_fully(fd, reinterpret_cast<char*>(header), 4, wait, timed_out);
  if (timed_out) return FrameRead::kTimedOut;
  if (got == 0) return FrameRead::kEnd;
  if (got < 4) throw ProtocolError(MessageId::protocol_frame_cut_short);
  const std::uint32_t size = header[0] | header[1] << 8 | header[2] << 16 | std::uint32_t(header[3]) << 24;
  if (size > max_bytes) throw ProtocolError({MessageId::protocol_frame_too_large, {{"bytes", std::to_string(size)}}});
  payload.resize(size);
  const std::size_t read = read_fully(fd, payload.data(), size, wait, timed_out);
  if (timed_out) return FrameRead::kTimedOut;
  if (read < size) throw ProtocolError(MessageId::protocol_frame_cut_short);
  return FrameRead::kFrame;
}

bool write_frame_waiting(int fd, const std::string& payload, const std::function<bool()>* wait) {
  const std::string frame = framed(payload);
  std::size_t done = 0;
  while (done < frame.size()) {
    if (wait && !(*wait)()) return false;
    const long long n = write_some(fd, frame.data() + done, frame.size() - done);
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK) continue;
      throw std::system_error(errno, std::generic_category(), "write");
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

ProtocolError::ProtocolError(Message what_was_wrong)
    : std::runtime_error(render(what_was_wrong, Language::English)), problem(std::move(what_was_wrong)) {}

bool read_frame(int fd, std::string& payload) {
  return read_frame_waiting(fd, payload, kMaxRequestBytes, nullptr) == FrameRead::kFrame;
}

void write_frame(int fd, const std::string& payload) { write_frame_waiting(fd, payload, nullptr); }

FrameRead read_frame(int fd, std::string& payload, std::uint32_t max_bytes, const std::function<bool()>& wait_readable) {
  return read_frame_waiting(fd, payload, max_bytes, &wait_readable);
}

bool write_frame(int fd, const std::string& payload, const std::function<bool()>& wait_writable) {
  return write_frame_waiting(fd, payload, &wait_writable);
}

std::string framed(const std::string& payload) {
  const auto size = static_cast<std::uint32_t>(payload.size());
  std::string frame;
  frame.reserve(4 + payload.size());
  for (int i = 0; i < 4; ++i) frame.push_back(static_cast<char>((size >> (8 * i)) & 0xff));
  frame += payload;
  return frame;
}

std::string cut_text(std::string text, std::size_t max_bytes, const char* marker) {
  if (text.size() <= max_bytes) return text;
  std::size_t end = max_bytes;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;  // not inside a character
  text.resize(end);
  return text + marker;
}

void put_lists(Writer& out, const std::vector<std::vector<std::uint32_t>>& lists) {
  std::vector<std::uint64_t> offsets{0};
  std::vector<std::uint32_t> values;
  for (const auto& list : lists) {
    values.insert(values.end(), list.begin(), list.end());
    offsets.push_back(values.size());
  }
  out.put_vector(offsets);
  out.put_vector(values);
}

std::vector<std::vector<std::uint32_t>> get_lists(Reader& in) {
  const auto offsets = in.get_vector<std::uint64_t>();
  const auto values = in.get_vector<std::uint32_t>();
  if (offsets.empty() || offsets.front() != 0 || offsets.back() != values.size()) throw ProtocolError(MessageId::protocol_malformed_lists);
  // Every offset checked before the lists are made: an empty list costs a vector's 24 bytes, so
  // a count of lists is believed only when the frame held the offsets that describe them.
  for (std::size_t i = 0; i + 1 < offsets.size(); ++i)
    if (offsets[i + 1] < offsets[i] || offsets[i + 1] > values.size()) throw ProtocolError(MessageId::protocol_malformed_lists);
  std::vector<std::vector<std::uint32_t>> lists(offsets.size() - 1);
  for (std::size_t i = 0; i + 1 < offsets.size(); ++i)
    lists[i].assign(values.begin() + static_cast<std::ptrdiff_t>(offsets[i]), values.begin() + static_cast<std::ptrdiff_t>(offsets[i + 1]));
  return lists;
}

void adopt_channels(int argc, char** argv) {
#if defined(_WIN32)
  // The judge (process_windows.cpp) passes the two inherited pipe handles as numbers.
  if (argc != 3) throw ProtocolError(MessageId::protocol_started_by_hand);
  const int modes[2] = {_O_RDONLY | _O_BINARY, _O_WRONLY | _O_BINARY};
  const int targets[2] = {kRequestFd, kReplyFd};
  for (int i = 0; i < 2; ++i) {
    const auto handle = static_cast<std::intptr_t>(std::strtoull(argv[1 + i], nullptr, 10));
    const int fd = ::_open_osfhandle(handle, modes[i]);
    if (fd < 0 || (fd != targets[i] && ::_dup2(fd, targets[i]) != 0))
      throw ProtocolError(MessageId::protocol_cannot_open_pipes);
  }
#else
  (void)argc;
  (void)argv;  // the judge put the pipes on descriptors 3 and 4 before exec (process_linux.cpp)
#endif
}

}  // namespace raylab::grading::protocol
