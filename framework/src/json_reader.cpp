#include "json_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace raylab {
namespace {

// What nlohmann-json would only find the hard way, checked before it parses, each named with
// its line and column: nesting deeper than kMaxJsonDepth (a million '[' would make every later
// recursive walk of the document, such as printing it in a message, overflow the stack) and
// numbers beyond a double (nlohmann throws out_of_range for them, with no place). Strings
// and comments are skipped as nlohmann reads them; anything else malformed is left to it.
void check_json_limits(const std::string& text, const std::string& source) {
  int depth = 0;
  std::size_t line = 1, line_start = 0;
  auto fail = [&](std::size_t at, const std::string& what) {
    throw InputError(source + ": not valid JSON: line " + std::to_string(line) + ", column " +
                     std::to_string(at - line_start + 1) + ": " + what);
  };
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n; ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = i + 1;
    } else if (c == '"') {  // a string: skip to its closing quote (escapes included)
      for (++i; i < n && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
        else if (text[i] == '\n') return;  // not valid JSON: nlohmann names the place
    } else if (c == '/' && i + 1 < n && text[i + 1] == '/') {
      while (i + 1 < n && text[i + 1] != '\n') ++i;
    } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {
      for (i += 2; i + 1 < n && !(text[i] == '*' && text[i + 1] == '/'); ++i)
        if (text[i] == '\n') {
          ++line;
          line_start = i + 1;
        }
      ++i;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        fail(i, "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels of [ ] and { }");
    } else if (c == ']' || c == '}') {
      --depth;
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = i;
      while (end < n && (text[end] == '-' || text[end] == '+' || text[end] == '.' ||
                         text[end] == 'e' || text[end] == 'E' || (text[end] >= '0' && text[end] <= '9')))
        ++end;
      const std::string number = text.substr(i, end - i);
      errno = 0;
      const double value = std::strtod(number.c_str(), nullptr);
      if (errno == ERANGE && std::fabs(value) == HUGE_VAL)  // overflow (underflow is fine)
        fail(i, "the number " + (number.size() > 40 ? number.substr(0, 37) + "..." : number) +
                    " is too large (beyond a double, about 1.8e308)");
      i = end - 1;
    }
  }
}

}  // namespace

json parse_json_text(const std::string& text, const std::string& source) {
  check_json_limits(text, source);
  json root;
  try {
    root = json::parse(text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    // nlohmann's text is "[json.exception.parse_error.101] parse error at line L, column C: ...".
    std::string what = e.what();
    const std::string marker = "parse error at ";
    const auto at = what.find(marker);
    if (at != std::string::npos) what = what.substr(at + marker.size());
    throw InputError(source + ": not valid JSON: " + what);
  } catch (const json::exception& e) {  // anything check_json_limits did not foresee
    throw InputError(source + ": not valid JSON: " + e.what());
  }
  return root;
}

}  // namespace raylab
