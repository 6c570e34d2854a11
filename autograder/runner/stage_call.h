// How a stage's calls between the judge and the stage server are written. Each stage has its
// own file of calls in autograder/suites/ (stages.json: "calls", e.g. 02_sphere_calls.cpp),
// compiled twice:
//   - into the judge, with RAYLAB_JUDGE 1: the stage's functions defined as requests to the
//     stage server (call_remote, or remote with a reader that checks every size and index of
//     the reply: a malformed reply is a protocol::ProtocolError, never a result);
//   - into the programs that link stage code (the stage server, autograder-regenerate), with
//     RAYLAB_JUDGE 0: a handler per call, registered with serve(), that reads the arguments,
//     calls the stage code and writes its result.
// Both sides name the call by one StageCall, so the file holds the whole of each call's format:
//
//   constexpr StageCall kIntersectRaySphere{"intersect_ray_sphere", "intersect_ray_sphere"};
//   #if RAYLAB_JUDGE
//   std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& c, float r) {
//     return call_remote<decltype(intersect_ray_sphere)>(kIntersectRaySphere, ray, c, r);
//   }
//   #else
//   const bool kServed = serve(kIntersectRaySphere, call_local<&intersect_ray_sphere>);
//   #endif
//
// call_remote and call_local send the arguments and the result as the function's declared types
// (plain values, std::optional, std::vector, std::string); a call that does more (a batch, a
// tree, a picture) writes and reads its own format with protocol::Writer and protocol::Reader. A
// stage function whose arguments cannot be sent (a RenderContext) is reached only through such a
// batch call, and the judge's definition of it throws std::logic_error (08_direct_light_calls.cpp).
#pragma once

#include "protocol.h"
#include "stage_session.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#ifndef RAYLAB_JUDGE
#error "a stage's calls file is compiled with RAYLAB_JUDGE 1 (the judge) or 0 (programs that link stage code)"
#endif

namespace raylab::grading {

// ---- The values of a call: plain values copied bytewise, optional, vector and string.

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};
template <class T>
struct IsVector : std::false_type {};
template <class T, class Allocator>
struct IsVector<std::vector<T, Allocator>> : std::true_type {};

template <class T>
void put_value(protocol::Writer& out, const T& value) {
  if constexpr (IsOptional<T>::value) out.put_optional(value);
  else if constexpr (IsVector<T>::value) out.put_vector(value);
  else if constexpr (std::is_same_v<T, std::string>) out.put_string(value);
  else out.put(value);
}

template <class T>
T get_value(protocol::Reader& in) {
  if constexpr (IsOptional<T>::value) return in.get_optional<typename T::value_type>();
  else if constexpr (IsVector<T>::value) return in.get_vector<typename T::value_type, typename T::allocator_type>();
  else if constexpr (std::is_same_v<T, std::string>) return in.get_string();
  else return in.get<T>();
}

// A function type's result and its parameters as values.
template <class Function>
struct Signature;
template <class Result, class... Parameters>
struct Signature<Result(Parameters...)> {
  using ResultType = Result;
  using Arguments = std::tuple<std::decay_t<Parameters>...>;
};

template <class T, class Allocator>
bool same_bytes(const std::vector<T, Allocator>& a, const std::vector<T, Allocator>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// ---- The judge's side (RAYLAB_JUDGE 1).

// How long a reply may be: room for the stage's exception (a kThrow frame, whose three texts the
// judge cuts at protocol::kMaxExceptionTextBytes) plus `result_bytes`, the most the call's result
// can take. The judge reads no more (StageSession::call): a reply's size follows from its request.
inline std::uint32_t reply_limit(std::uint64_t result_bytes) {
  constexpr std::uint64_t kExceptionRoom = 16u << 10;
  return static_cast<std::uint32_t>(std::min<std::uint64_t>(kExceptionRoom + result_bytes, protocol::kMaxRequestBytes));
}
// The reply limit of a batch call whose result is at most kResultPerRequestByte times its request
// (a tree for its boxes, a sample for its random numbers, hits for rays); calls whose results can
// be larger (pictures, samples per query, hit lists) give their own (remote's max_reply_bytes).
constexpr std::uint64_t kResultPerRequestByte = 64;

// One request to the current stage server (StageSession::call: a lost server throws StageLost,
// a stage exception is rethrown). `read(reply)` reads the result from the reply and checks it;
// every byte of the reply must be read, and a reply that does not pass read's checks (a
// protocol::ProtocolError) loses the call as a malformed frame does. on_callback answers the
// server's questions during the call (ask_judge below). A reader that checks the result's sizes
// and indices calls in.expect_end() first, so that a reply with extra bytes is reported as such.
// max_reply_bytes: 0 for kResultPerRequestByte times the request's size.
template <class Read>
auto remote(const StageCall& call, const protocol::Writer& arguments, Read read,
            const StageSession::Callback& on_callback = {}, std::uint32_t max_reply_bytes = 0) {
  if (max_reply_bytes == 0) max_reply_bytes = reply_limit(kResultPerRequestByte * arguments.bytes().size());
  StageSession& session = StageSession::instance();
  const std::string reply = session.call(call, arguments, max_reply_bytes, on_callback);
  try {
    protocol::Reader in(reply);
    in.get<std::uint8_t>();  // kReturn
    auto result = read(in);
    in.expect_end();
    return result;
  } catch (const protocol::ProtocolError& e) {
    session.reject_reply(call, e.problem);
  }
}

// The bytes a result of a call_remote takes in its reply, when bounded by its type (plain values
// and optionals); 0 when not (a vector or a text: then the request's rule of remote()).
template <class T>
constexpr std::uint64_t fixed_result_bytes() {
  if constexpr (IsVector<T>::value || std::is_same_v<T, std::string>) return 0;
  else if constexpr (IsOptional<T>::value) return 1 + sizeof(typename T::value_type);
  else return sizeof(T);
}

// A stage function of plain values, as a request: call_remote<decltype(f)>(call, arguments...).
template <class Function, class... Values>
typename Signature<Function>::ResultType call_remote(const StageCall& call, const Values&... arguments) {
  using Result = typename Signature<Function>::ResultType;
  const typename Signature<Function>::Arguments values{arguments...};
  protocol::Writer out;
  std::apply([&](const auto&... value) { (put_value(out, value), ...); }, values);
  constexpr std::uint64_t result_bytes = fixed_result_bytes<Result>();
  return remote(call, out, [](protocol::Reader& in) { return get_value<Result>(in); }, {},
                result_bytes > 0 ? reply_limit(1 + result_bytes) : 0);
}

// The request that carries many calls of one stage function (call_remote_each): the call's name,
// their count, then each call's arguments. The stage server runs the named call's handler once
// per set of arguments, and the reply holds the results one after the other.
inline constexpr StageCall kEachCall{"each", "each"};

// Many calls of a stage function of plain values in one request, for a test of thousands of
// inputs (a round trip costs more than such a call): the results in the order of `calls`, each
// as call_remote<Function>(call, ...) returns it. A stage exception in any of them is thrown as
// call_remote throws it, and a lost server's message names `call`, as for one call.
template <class Function>
std::vector<typename Signature<Function>::ResultType> call_remote_each(
    const StageCall& call, const std::vector<typename Signature<Function>::Arguments>& calls) {
  using Result = typename Signature<Function>::ResultType;
  constexpr std::uint64_t result_bytes = fixed_result_bytes<Result>();
  static_assert(result_bytes > 0, "call_remote_each: a function whose result has a fixed size");
  protocol::Writer out;
  out.put_string(call.name);
  out.put<std::uint64_t>(calls.size());
  for (const auto& values : calls) std::apply([&](const auto&... value) { (put_value(out, value), ...); }, values);
  const StageCall each{kEachCall.name, call.description, call.during};
  return remote(each, out, [&](protocol::Reader& in) {
    std::vector<Result> results;
    results.reserve(calls.size());
    for (std::size_t i = 0; i < calls.size(); ++i) results.push_back(get_value<Result>(in));
    return results;
  }, {}, reply_limit(calls.size() * result_bytes));
}

// A list that the stage server keeps between calls, sent only when the current server does not
// hold an equal one (stage 05's tree and mesh go once, not with each of thousands of rays). The
// server reads it with receive().
template <class T, class Allocator = std::allocator<T>>
class SentList {
 public:
  // Writes the list, or that the server holds it already.
  void put(protocol::Writer& out, const std::vector<T, Allocator>& values) {
    const StageSession& session = StageSession::instance();
    // A server that is not running yet starts fresh during the call, holding nothing.
    sending_ = !(held_ && session.server_running() && generation_ == session.server_generation() &&
                 same_bytes(sent_, values));
    out.put<std::uint8_t>(sending_);
    if (sending_) out.put_vector(values);
  }
  // After the call returned: the server holds what put() wrote.
  void returned(const std::vector<T, Allocator>& values) {
    generation_ = StageSession::instance().server_generation();
    if (sending_) {
      sent_ = values;
      held_ = true;
    }
  }

 private:
  std::vector<T, Allocator> sent_;
  unsigned generation_ = 0;
  bool held_ = false, sending_ = false;
};

// ---- The stage server's side (RAYLAB_JUDGE 0).

// Reads a call's arguments from `arguments` and writes its result to `result`; throws what the
// stage code throws.
using Handler = void (*)(protocol::Reader& arguments, protocol::Writer& result);

// Registers the handler of `call`, at static initialisation: const bool kServed = serve(...).
// Throws std::logic_error when another call has the same name.
bool serve(const StageCall& call, Handler handler);
// The handler of a call's name, or nullptr (the stage server's main loop).
Handler find_handler(const std::string& name);

template <class... T>
std::tuple<T...> get_values(protocol::Reader& in, std::tuple<T...>*) {
  return std::tuple<T...>{get_value<T>(in)...};  // a braced list: read in order
}

// The handler of a stage function of plain values: serve(call, call_local<&function>).
template <auto function>
void call_local(protocol::Reader& in, protocol::Writer& out) {
  using Arguments = typename Signature<std::remove_pointer_t<decltype(function)>>::Arguments;
  const Arguments arguments = get_values(in, static_cast<Arguments*>(nullptr));
  put_value(out, std::apply(function, arguments));
}

// call_remote_each's counterpart where the stage code is linked (the regenerate tool runs the
// suites' calls in place): function on each set of arguments, in order.
template <auto function, class Arguments>
auto call_local_each(const std::vector<Arguments>& calls) {
  std::vector<decltype(std::apply(function, calls.front()))> results;
  results.reserve(calls.size());
  for (const Arguments& arguments : calls) results.push_back(std::apply(function, arguments));
  return results;
}

// During a call, in the stage server: sends the judge a question (answered by the on_callback
// of the judge's remote()) and returns the answer. Ends the server when the judge has gone.
std::string ask_judge(const protocol::Writer& question);

// The server's side of a SentList: `held` becomes the list the judge sent, if it sent it again.
template <class T, class Allocator>
void receive(protocol::Reader& in, std::vector<T, Allocator>& held) {
  if (in.get<std::uint8_t>()) held = in.get_vector<T, Allocator>();
}

}  // namespace raylab::grading
