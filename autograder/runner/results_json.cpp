#include "results.h"

#include "gradescope.h"
#include "protocol.h"

#include <nlohmann/json.hpp>

#if defined(_WIN32)
#include <fcntl.h>
#include <io.h>
#include <share.h>
#include <sys/stat.h>
#else
#include <sys/stat.h>
#include <unistd.h>
#endif

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <system_error>

namespace raylab::grading {
namespace {

// Creates a new file in `directory` under a random name starting with `prefix` (set in `name`), readable by everyone,
// failing rather than opening anything that exists there already. Returns its descriptor or -1.
int create_exclusive_file(const std::filesystem::path& directory, const std::string& prefix, std::string& name) {
#if defined(_WIN32)
  std::random_device random;
  for (int attempt = 0; attempt < 100; ++attempt) {
    name = (directory / (prefix + std::to_string(random()))).string();
    int fd = -1;
    if (::_sopen_s(&fd, name.c_str(), _O_CREAT | _O_EXCL | _O_WRONLY | _O_BINARY, _SH_DENYNO, _S_IREAD | _S_IWRITE) == 0)
      return fd;
    if (errno != EEXIST) return -1;
  }
  return -1;
#else
  name = (directory / (prefix + "XXXXXX")).string();
  const int fd = ::mkstemp(name.data());
  if (fd >= 0) ::fchmod(fd, 0644);
  return fd;
#endif
}

#if defined(_WIN32)
long long write_some(int fd, const char* data, std::size_t size) { return ::_write(fd, data, static_cast<unsigned>(size)); }
int close_file(int fd) { return ::_close(fd); }
#else
long long write_some(int fd, const char* data, std::size_t size) { return ::write(fd, data, size); }
int close_file(int fd) { return ::close(fd); }
#endif

}  // namespace

void write_results_json(const std::vector<StageResult>& results, const std::string& path, const GradescopeOptions& options) {
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
                            {"output", test_markdown(t, Language::English)},
                            {"output_zh", test_markdown(t, Language::Chinese)},
                            {"output_format", "md"},
                            {"hints", hints},
                            {"execution_time", t.seconds},
                            {"visibility", test_visibility(stage, t, options.visibility)}});
      earned += t.earned();
      max += t.info.points;
    }
  const json results_json = {{"score", earned},
                             {"max_score", max},
                             {"execution_time", options.run_seconds},
                             {"tests", tests_json},
                             {"leaderboard", leaderboard(results)}};
  replace_file(path, results_json.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

void replace_file(const std::string& path, const std::string& text) {
  // A new file with a name no one could know in advance (created exclusively: O_EXCL), renamed
  // over the target: whatever was at `path` before, a file or a link planted there, is replaced.
  const std::filesystem::path target(path);
  const std::filesystem::path directory = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::string temporary;
  const int fd = create_exclusive_file(directory, "." + target.filename().string() + ".", temporary);
  if (fd < 0) throw std::runtime_error("cannot write in " + directory.string() + ": " + std::strerror(errno));
  std::size_t written = 0;
  while (written < text.size()) {
    const auto n = write_some(fd, text.data() + written, text.size() - written);
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  const bool ok = written == text.size() && close_file(fd) == 0;
  std::error_code renamed;
  if (ok) std::filesystem::rename(temporary, target, renamed);  // replaces an existing target, also on Windows
  if (!ok || renamed) {
    std::filesystem::remove(temporary, renamed);
    throw std::runtime_error("cannot write " + path);
  }
}

void write_compile_failure_json(const std::string& build_log, const std::string& path) {
  std::ifstream in(build_log, std::ios::binary);
  std::vector<std::string> errors;
  for (std::string line; errors.size() < 20 && std::getline(in, line);)
    if (line.find("error") != std::string::npos || line.find("Error") != std::string::npos)
      errors.push_back(shown_as_text(protocol::cut_text(line, 300)));
  auto output = [&](Language language) {
    std::string text = render(MessageId::gradescope_did_not_compile, language) + "\n\n";
    if (errors.empty()) return text + render(MessageId::gradescope_no_error_lines, language) + "\n";
    for (const std::string& line : errors) text += "    " + line + "\n";  // a code block: nothing in it is live
    return text;
  };
  const nlohmann::json results = {{"score", 0},
                                  {"output", output(Language::English)},
                                  {"output_zh", output(Language::Chinese)},
                                  {"output_format", "md"},
                                  {"tests", nlohmann::json::array()}};
  replace_file(path, results.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

}  // namespace raylab::grading
