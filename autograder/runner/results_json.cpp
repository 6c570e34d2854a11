#include "results.h"

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace raylab::grading {

void write_results_json(const std::vector<StageResult>& results, const std::string& path) {
  using nlohmann::json;
  json tests_json = json::array();
  int earned = 0, max = 0;
  for (const StageResult& stage : results)
    for (const TestResult& t : stage.tests) {
      // The hints as the catalogue names them (messages.def), for tools; "output" is what a student reads.
      json hints = json::array();
      for (const Message& hint : t.hints)
        hints.push_back({{"id", std::string(message_name(hint.id))},
                         {"text", render(hint, Language::English)},
                         {"text_zh", render(hint, Language::Chinese)}});
      tests_json.push_back({{"name", stage.stage->id + ": " + t.info.name},
                            {"score", t.earned()},
                            {"max_score", t.info.points},
                            {"output", test_output(t, Language::English)},
                            {"output_zh", test_output(t, Language::Chinese)},
                            {"hints", hints},
                            {"visibility", "visible"}});
      earned += t.earned();
      max += t.info.points;
    }
  const json results_json = {{"score", earned}, {"max_score", max}, {"tests", tests_json}};
  const std::string text = results_json.dump(2, ' ', false, json::error_handler_t::replace) + "\n";

  // A new file with a name no one could know in advance (mkstemp: O_EXCL), renamed over the
  // target: whatever was at `path` before, a file or a link planted there, is replaced.
  const std::filesystem::path target(path);
  const std::filesystem::path directory = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::string temporary = (directory / ".results.json.XXXXXX").string();
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) throw std::runtime_error("cannot write in " + directory.string() + ": " + std::strerror(errno));
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  ::fchmod(fd, 0644);
  const bool ok = written == text.size() && ::close(fd) == 0;
  if (!ok || std::rename(temporary.c_str(), path.c_str()) != 0) {
    ::unlink(temporary.c_str());
    throw std::runtime_error("cannot write " + path);
  }
}

}  // namespace raylab::grading
