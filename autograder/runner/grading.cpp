#include "grading.h"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <set>

namespace raylab::grading {
namespace {

std::vector<StageInfo>& stage_registry() {
  static std::vector<StageInfo> registry;
  return registry;
}
std::vector<TestInfo>& test_registry() {
  static std::vector<TestInfo> registry;
  return registry;
}

struct CurrentTest {
  std::vector<std::string> hints, notes;
};
CurrentTest& current() {
  static CurrentTest test;
  return test;
}

std::string& output_directory_storage() {
  static std::string directory = "grading-output";
  return directory;
}
std::set<int>& incomplete_dependencies() {
  static std::set<int> stages;
  return stages;
}

// Writes one JSON line per event with write(2): it is in the kernel before the next test runs.
class Reporter : public ::testing::EmptyTestEventListener {
 public:
  explicit Reporter(int fd) : fd_(fd) {}

  void OnTestStart(const ::testing::TestInfo& info) override {
    current() = CurrentTest{};
    messages_.clear();
    write_line({{"event", "start"}, {"test", full_name(info)}});
  }

  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (!result.failed()) return;
    std::string message = result.message();
    if (message.size() > 1500) message = message.substr(0, 1500) + " [...]";
    messages_.push_back(message);
  }

  void OnTestEnd(const ::testing::TestInfo& info) override {
    bool not_implemented = false;
    for (const std::string& message : messages_)
      not_implemented = not_implemented || message.find("is not implemented yet") != std::string::npos;
    write_line({{"event", "end"},
                {"test", full_name(info)},
                {"passed", info.result()->Passed()},
                {"not_implemented", not_implemented},
                {"messages", messages_},
                {"hints", current().hints},
                {"notes", current().notes}});
  }

 private:
  static std::string full_name(const ::testing::TestInfo& info) {
    return std::string(info.test_suite_name()) + "." + info.name();
  }
  void write_line(const nlohmann::json& event) {
    const std::string line = event.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    std::size_t written = 0;
    while (written < line.size()) {
      const ssize_t n = ::write(fd_, line.data() + written, line.size() - written);
      if (n <= 0) return;
      written += static_cast<std::size_t>(n);
    }
  }
  int fd_;
  std::vector<std::string> messages_;
};

}  // namespace

bool register_stage(StageInfo stage) {
  stage_registry().push_back(std::move(stage));
  std::sort(stage_registry().begin(), stage_registry().end(),
            [](const StageInfo& a, const StageInfo& b) { return a.number < b.number; });
  return true;
}

bool register_test(int stage, const char* suite, const char* name, int points) {
  test_registry().push_back({stage, suite, name, points});
  return true;
}

const std::vector<StageInfo>& stages() { return stage_registry(); }

const StageInfo* find_stage(int number) {
  for (const StageInfo& stage : stage_registry())
    if (stage.number == number) return &stage;
  return nullptr;
}

std::string handout_of(const StageInfo& stage) {
  return stage.handout.empty() ? "docs/" + stage.id + ".md" : stage.handout;
}

const std::vector<TestInfo>& tests() { return test_registry(); }

void add_hint(const std::string& hint) {
  auto& hints = current().hints;
  if (std::find(hints.begin(), hints.end(), hint) == hints.end()) hints.push_back(hint);
}

void add_note(const std::string& note) { current().notes.push_back(note); }

const std::string& output_directory() { return output_directory_storage(); }
void set_output_directory(const std::string& directory) { output_directory_storage() = directory; }

std::string reference_path(const std::string& name) {
  return std::string(RAYLAB_REFERENCE_DIR) + "/" + name;
}

void install_reporter(const std::string& report_path) {
  const int fd = ::open(report_path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot open the report file " + report_path);
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  listeners.Append(new Reporter(fd));
}

void set_incomplete_dependencies(const std::vector<int>& stage_numbers) {
  incomplete_dependencies() = std::set<int>(stage_numbers.begin(), stage_numbers.end());
}

bool dependency_incomplete(int stage_number) { return incomplete_dependencies().count(stage_number) > 0; }

void hint_about_dependencies(int stage_number) {
  const StageInfo* stage = find_stage(stage_number);
  if (!stage) return;
  for (int earlier : stage->depends_on)
    if (dependency_incomplete(earlier)) {
      const StageInfo* dependency = find_stage(earlier);
      add_hint("this picture is rendered with your stage " + (dependency ? dependency->id : std::to_string(earlier)) +
               ", which is not complete yet: finish it first, then this test means something");
    }
}

}  // namespace raylab::grading
