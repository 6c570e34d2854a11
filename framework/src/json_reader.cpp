#include "json_reader.h"

namespace raylab {

json parse_json_text(const std::string& text, const std::string& source) {
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
  }
  return root;
}

}  // namespace raylab
