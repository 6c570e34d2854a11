// The protocol between the judge (the autograder process that decides scores and never runs
// student code) and a stage server (a child process that links the student's stage library and
// answers one call at a time). See docs/instructors.md, "The grader's trust model".
//
// Frames on a pipe: a 4-byte little-endian payload length, then the payload. A request is
//   [kCall] [call name] [arguments...]
// where the name is one of the stages' calls (stage_call.h: each stage's calls file in
// autograder/suites/ writes its arguments and reads its result), and the stage server answers
// with one of
//   [kReturn] [result...]                                   the function returned
//   [kThrow] [ExceptionKind] [message] [stage id] [function]  it threw
//   [kCallback] [question...]                               the call asks the judge something
//                                                           (stage_call.h: ask_judge); the judge
//                                                           answers [kReturn] [answer...]
// The judge treats everything it reads as untrusted: a malformed frame is an error of the call
// (ProtocolError), never a result. Values are the framework's plain structs, copied bytewise
// (both ends are the same build on the same machine).
#pragma once

#include "messages.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <memory>
#include <vector>

namespace raylab::grading::protocol {

// The stage server reads requests from this descriptor and writes replies to the next.
constexpr int kRequestFd = 3, kReplyFd = 4;
// The stage server's first call: puts the pipes the judge gave it on kRequestFd and kReplyFd
// (Linux: already there; Windows: the handles named by its two arguments). Throws ProtocolError.
void adopt_channels(int argc, char** argv);
// The largest frame the stage server reads from the judge (the judge's own requests: meshes,
// trees). What the judge reads is bounded per call, by the call's reply limit (stage_call.h).
constexpr std::uint32_t kMaxRequestBytes = 512u << 20;
// The longest exception text the judge keeps of a stage's kThrow reply (the stage server cuts
// its own texts there too): a longer one is cut, never shown whole.
constexpr std::size_t kMaxExceptionTextBytes = 4096;
// The largest question a stage server may ask the judge during a call (kCallback: a ray and an
// index today).
constexpr std::size_t kMaxCallbackBytes = 64u << 10;

enum Kind : std::uint8_t { kCall = 1, kReturn = 2, kThrow = 3, kCallback = 4 };

// What the stage code threw. OutOfMemory (std::bad_alloc) carries no text: the judge words it in
// the run's language (stage_out_of_memory), never with text made by the stage process.
// BrokenTree (raylab/bvh_tools.h: BrokenBvh) is followed by the mesh's name (or nothing: the scene's
// objects), then the BvhViolation and the number of boxes: the judge words it.
enum class ExceptionKind : std::uint8_t { NotImplemented = 1, InvalidArgument, Other, OutOfMemory, BrokenTree };

// The reply was not a well-formed frame: what a child wrote is not a result. `problem` says
// what was wrong (a protocol_... entry of messages.def); what() is its English text.
struct ProtocolError : std::runtime_error {
  explicit ProtocolError(Message what_was_wrong);
  Message problem;
};

class Writer {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* bytes = reinterpret_cast<const char*>(&value);
    data_.append(bytes, sizeof(T));
  }
  template <class T, class Allocator>
  void put_vector(const std::vector<T, Allocator>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(values.size());
    data_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  void put_string(const std::string& text) {
    put<std::uint64_t>(text.size());
    data_ += text;
  }
  template <class T>
  void put_optional(const std::optional<T>& value) {
    put<std::uint8_t>(value.has_value());
    put(value.value_or(T{}));
  }
  const std::string& bytes() const { return data_; }
  std::string& bytes() { return data_; }

 private:
  std::string data_;
};

class Reader {
 public:
  explicit Reader(const std::string& data) : data_(data) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  template <class T, class Allocator = std::allocator<T>>
  std::vector<T, Allocator> get_vector() {
    const auto count = get<std::uint64_t>();
    if (count > (data_.size() - offset_) / sizeof(T)) throw ProtocolError(MessageId::protocol_list_too_long);
    std::vector<T, Allocator> values(count);
    if (count) std::memcpy(values.data(), take(count * sizeof(T)), count * sizeof(T));
    return values;
  }
  std::string get_string() {
    const auto size = get<std::uint64_t>();
    if (size > data_.size() - offset_) throw ProtocolError(MessageId::protocol_text_too_long);
    return std::string(take(size), size);
  }
  template <class T>
  std::optional<T> get_optional() {
    const bool has = get<std::uint8_t>() != 0;
    const T value = get<T>();
    return has ? std::optional<T>(value) : std::nullopt;
  }
  void expect_end() const {
    if (offset_ != data_.size()) throw ProtocolError(MessageId::protocol_extra_bytes);
  }

 private:
  const char* take(std::size_t size) {
    if (size > data_.size() - offset_) throw ProtocolError(MessageId::protocol_reply_too_short);
    const char* at = data_.data() + offset_;
    offset_ += size;
    return at;
  }
  const std::string& data_;
  std::size_t offset_ = 0;
};

// Whole frames on a blocking descriptor (the stage server's side). read_frame returns false at end
// of file before a frame starts; both throw ProtocolError on a short frame or one over
// kMaxRequestBytes, std::system_error on I/O errors.
bool read_frame(int fd, std::string& payload);
void write_frame(int fd, const std::string& payload);

// The judge's side: frames on a non-blocking descriptor, with a wait before every read or write
// that returns false once the call's deadline has passed. So a partial frame, or a server that
// stops reading, costs its call's time and no more. A frame over max_bytes is a ProtocolError
// as soon as its header is read, before anything is allocated for it.
enum class FrameRead { kFrame, kEnd, kTimedOut };
FrameRead read_frame(int fd, std::string& payload, std::uint32_t max_bytes, const std::function<bool()>& wait_readable);
bool write_frame(int fd, const std::string& payload, const std::function<bool()>& wait_writable);  // false: timed out

// A payload as a frame: its 4-byte little-endian length, then itself.
std::string framed(const std::string& payload);

// A text cut to at most max_bytes, at a UTF-8 character's start, with `marker` after a cut.
std::string cut_text(std::string text, std::size_t max_bytes, const char* marker = "...");

using Triangle = std::array<glm::vec3, 3>;

// Lists of lists, flattened: list i is values[offsets[i] .. offsets[i + 1]).
void put_lists(Writer& out, const std::vector<std::vector<std::uint32_t>>& lists);
std::vector<std::vector<std::uint32_t>> get_lists(Reader& in);

}  // namespace raylab::grading::protocol
