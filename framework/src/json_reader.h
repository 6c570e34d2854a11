// Reading values out of a parsed JSON document (nlohmann-json), each error naming the
// source file, the JSON path (RFC 6901, e.g. /objects/2/radius) and what was expected.
// Private to the framework: the scene schema (scene_schema.cpp) reads scene files with it.
#pragma once

#include "raylab/error.h"
#include "raylab/math.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <initializer_list>
#include <sstream>
#include <string>

namespace raylab {

using nlohmann::json;

// How deeply [ ] and { } may nest in a file read with parse_json_text (scenes need 4).
constexpr int kMaxJsonDepth = 64;

// Parses JSON text (comments allowed); throws InputError "SOURCE: not valid JSON: line L,
// column C: ..." if it is not JSON, nests deeper than kMaxJsonDepth or holds a number beyond
// a double.
json parse_json_text(const std::string& text, const std::string& source);

// Reads values out of a parsed document, naming the JSON path of anything wrong.
class JsonReader {
 public:
  explicit JsonReader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(source_ + ": at " + (path.empty() ? "/" : path) + ": " + what);
  }

  const std::string& source() const { return source_; }

  void expect_object(const json& value, const std::string& path) const {
    if (!value.is_object()) fail(path, "expected an object {...}, got " + describe(value));
  }

  // Rejects keys outside `allowed`: a typo must not be silently ignored.
  void check_keys(const json& object, const std::string& path,
                  std::initializer_list<const char*> allowed) const {
    for (const auto& item : object.items()) {
      bool known = false;
      std::string list;
      for (const char* key : allowed) {
        known = known || item.key() == key;
        list += std::string(list.empty() ? "" : ", ") + key;
      }
      if (!known) fail(path + "/" + item.key(), "unknown key '" + item.key() + "' (expected one of: " + list + ")");
    }
  }

  const json& require(const json& object, const std::string& path, const char* key) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(path, std::string("missing key '") + key + "'");
    return *it;
  }

  double number(const json& value, const std::string& path, double min, double max) const {
    if (!value.is_number()) fail(path, "expected a number, got " + describe(value));
    const double x = value.get<double>();
    if (!std::isfinite(x) || x < min || x > max) {
      std::ostringstream what;
      what << "expected a number in [" << min << ", " << max << "], got " << value.dump();
      fail(path, what.str());
    }
    return x;
  }

  int integer(const json& value, const std::string& path, long long min, long long max) const {
    if (!value.is_number_integer()) fail(path, "expected a whole number, got " + describe(value));
    // A whole number above the largest long long (up to 2^64 - 1) is stored unsigned.
    const long long x = value.is_number_unsigned() && value.get<unsigned long long>() > 1ULL << 62
                            ? (1LL << 62) : value.get<long long>();
    if (x < min || x > max)
      fail(path, "expected a whole number in [" + std::to_string(min) + ", " +
                     std::to_string(max) + "], got " + value.dump());
    return static_cast<int>(x);
  }

  std::string string(const json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, "expected a string, got " + describe(value));
    return value.get<std::string>();
  }

  template <int N>
  glm::vec<N, float> vector(const json& value, const std::string& path) const {
    if (!value.is_array() || value.size() != N)
      fail(path, "expected an array of " + std::to_string(N) + " numbers, got " + describe(value));
    glm::vec<N, float> v;
    for (int i = 0; i < N; ++i)
      v[i] = static_cast<float>(number(value[i], path + "/" + std::to_string(i), -1e30, 1e30));
    return v;
  }

  // A colour: three numbers >= 0, or one number for grey. `what` names it in messages
  // ("colour", "radiance", "intensity", ...).
  glm::vec3 color(const json& value, const std::string& path, const char* what = "colour") const {
    if (value.is_number()) {
      if (value.get<double>() < 0) fail(path, std::string(what) + " must be >= 0, got " + value.dump());
      return glm::vec3(static_cast<float>(number(value, path, 0, 1e6)));
    }
    const glm::vec3 c = vector<3>(value, path);
    if (c.x < 0 || c.y < 0 || c.z < 0) fail(path, std::string(what) + " components must be >= 0, got " + value.dump());
    return c;
  }

  static std::string describe(const json& value) {
    std::string text = value.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return std::string(value.type_name()) + " " + text;
  }

 private:
  std::string source_;
};

}  // namespace raylab
