#include "gradescope.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>

namespace raylab::grading {
namespace {

const char* const kLevels[] = {"visible", "hidden", "after_due_date", "after_published"};

// `text` matches `pattern`, where * stands for any run of characters.
bool wildcard_match(const std::string& pattern, const std::string& text) {
  std::size_t p = 0, t = 0, star = std::string::npos, resume = 0;
  while (t < text.size()) {
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = t;
    } else if (p < pattern.size() && pattern[p] == text[t]) {
      ++p;
      ++t;
    } else if (star != std::string::npos) {
      p = star + 1;
      t = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::string base64(const std::string& bytes) {
  static const char* const digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    unsigned value = 0;
    for (std::size_t k = 0; k < 3; ++k)
      value = value << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? digits[(value >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

// The numbers a note of `id` carries as `arg`, or nullopt.
std::optional<double> note_number(const TestResult& test, MessageId id, const char* arg) {
  for (const Message& note : test.notes) {
    if (note.id != id) continue;
    for (const MessageArg& a : note.args)
      if (a.name == arg) {
        char* end = nullptr;
        const double value = std::strtod(a.text.c_str(), &end);
        if (end != a.text.c_str()) return value;
      }
  }
  return std::nullopt;
}

}  // namespace

std::optional<VisibilityRule> parse_visibility_rule(const std::string& text, std::string& error) {
  const std::size_t equals = text.rfind('=');
  VisibilityRule rule;
  rule.pattern = equals == std::string::npos ? "" : text.substr(0, equals);
  rule.level = equals == std::string::npos ? text : text.substr(equals + 1);
  for (const char* level : kLevels)
    if (rule.level == level) return rule;
  error = "--visibility " + text + ": \"" + rule.level +
          "\" is not a Gradescope visibility (visible, hidden, after_due_date or after_published)";
  return std::nullopt;
}

std::string test_visibility(const StageResult& stage, const TestResult& test, const std::vector<VisibilityRule>& rules) {
  std::string level = "visible";
  const std::string name = stage.stage->id + ": " + test.info.name;
  for (const VisibilityRule& rule : rules) {
    const StageInfo* named = rule.pattern.empty() ? nullptr : find_stage(std::string_view(rule.pattern));
    if (rule.pattern.empty() || (named && named == stage.stage) || wildcard_match(rule.pattern, name)) level = rule.level;
  }
  return level;
}

std::string test_markdown(const TestResult& test, Language language) {
  std::string out;
  std::istringstream lines(test_output(test, language));
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) out += "- " + markdown_text(line) + "\n";
  if (test.earned() == test.info.points) return out;
  // The pictures named in the English text (the same files in either language), if the judge
  // wrote them: a file in the output folder (a text the stage code chose, such as an exception's,
  // may name any other file).
  static const std::regex png(R"([^\s:;,()]+\.png)");
  const std::string english = test_output(test, Language::English);
  std::error_code error;
  const std::filesystem::path pictures = std::filesystem::weakly_canonical(output_directory(), error);
  std::set<std::string> shown;
  for (auto match = std::sregex_iterator(english.begin(), english.end(), png); match != std::sregex_iterator(); ++match) {
    const std::string path = match->str();
    if (!shown.insert(path).second) continue;
    std::error_code path_error;
    const std::filesystem::path where = std::filesystem::weakly_canonical(path, path_error);
    if (error || path_error || where.parent_path() != pictures) continue;
    std::ifstream in(path, std::ios::binary);
    if (!in) continue;
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string name = path.substr(path.find_last_of('/') + 1);
    out += "\n![" + name + "](data:image/png;base64," + base64(bytes) + ")\n";
  }
  return out;
}

nlohmann::json leaderboard(const std::vector<StageResult>& results) {
  nlohmann::json entries = nlohmann::json::array();
  auto add = [&](const std::string& name, double value) {
    entries.push_back({{"name", name}, {"value", value}, {"order", "asc"}});  // less is better
  };
  for (const StageResult& stage : results)
    for (const TestResult& test : stage.tests) {
      if (const auto nodes = note_number(test, MessageId::note_bvh_work, "your_nodes"))
        add(stage.stage->id + ": nodes per ray", *nodes);
      if (const auto triangles = note_number(test, MessageId::note_bvh_work, "your_tests"))
        add(stage.stage->id + ": triangles per ray", *triangles);
      if (const auto cost = note_number(test, MessageId::note_bvh_sah_cost, "cost"))
        add(stage.stage->id + ": SAH cost", *cost);
      const bool image_test =
          std::any_of(test.notes.begin(), test.notes.end(), [](const Message& note) { return note.id == MessageId::note_image; });
      if (image_test && test.status == Status::Passed)
        add(stage.stage->id + ": picture seconds", std::round(test.seconds * 1000.0) / 1000.0);
    }
  return entries;
}

}  // namespace raylab::grading
