#include "grading.h"
#include "kit_folders.h"
#include "protocol.h"

#include "raylab/stage_table.h"

#include <algorithm>
#include <cctype>
#include <exception>
#include <stdexcept>

namespace raylab::grading {
namespace {

// The table's stages, built on first use (suites register during static initialisation, in
// any order of translation units: the table itself is ready whenever it is asked for).
std::vector<StageInfo>& stage_registry() {
  static std::vector<StageInfo> registry = [] {
    std::vector<StageInfo> rows;
    for (const StageDescription& description : stage_table()) {
      StageInfo stage;
      stage.number = static_cast<int>(rows.size()) + 1;
      stage.id = description.id;
      stage.title = description.display_title();
      stage.handout = description.handout_reference();
      // docs/zh/<name>.md is the Chinese twin of docs/<name>.md, with the same sections.
      const std::string handout(description.handout);
      const std::string handout_zh = "docs/zh/" + handout.substr(handout.rfind('/') + 1);
      stage.handout_file = handout;
      stage.handout_file_zh = handout_zh;
      Message handout_text = verbatim("");
      handout_text.args = {MessageArg::bilingual("text", handout, handout_zh)};
      if (!description.handout_section.empty())
        handout_text = {MessageId::console_handout_section,
                        {{"handout", handout_text}, {"section", std::string(description.handout_section)}}};
      stage.handout_text = handout_text;
      const std::string title(description.title);
      Message title_text = verbatim("");
      title_text.args = {MessageArg::bilingual("text", title, description.title_zh.empty() ? title : std::string(description.title_zh))};
      if (description.bonus) title_text = {MessageId::console_bonus_title, {{"title", title_text}}};
      stage.title_text = title_text;
      stage.points = description.points;
      stage.server_suffix = std::string(description.server_suffix);
      rows.push_back(stage);
    }
    return rows;
  }();
  return registry;
}
std::vector<std::string>& problem_registry() {
  static std::vector<std::string> problems;
  return problems;
}
StageInfo* mutable_stage(std::string_view name) {
  for (StageInfo& stage : stage_registry())
    if (stage.id == name) return &stage;
  return nullptr;
}
std::vector<TestInfo>& test_registry() {
  static std::vector<TestInfo> registry;
  return registry;
}

struct CurrentTest {
  std::vector<Message> hints, notes, hints_if_lost;
  std::vector<ImageComparison> images;
  std::vector<Message> failures;  // add_failure's, in order, until the listener has seen each
  std::vector<Message> thrown;    // exception_text's: the exceptions the judge threw in the test
};
CurrentTest& current() {
  static CurrentTest test;
  return test;
}

std::string& output_directory_storage() {
  static std::string directory = "grading-output";
  return directory;
}
std::string& reference_directory_storage() {
  static std::string directory = kit_reference_folder();
  return directory;
}

// A value that is not a number reads as what it is in every failure text, hint and note of
// every stage: the stream's and std::to_string's "nan", "-nan", "inf", "-inf" (whole words)
// become "NaN" and "infinity" / "-infinity" (in Chinese: "NaN" and "无穷大" / "负无穷大", the
// terms of docs/glossary.md).
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
std::string name_non_finite(const std::string& text, Language language = Language::English) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const bool word_start = i == 0 || !is_word_char(text[i - 1]);
    const std::size_t sign = word_start && (text[i] == '-' || text[i] == '+') ? 1 : 0;
    const bool starts_word = word_start && (sign == 0 || i + 1 < text.size());
    const std::string rest = starts_word ? text.substr(i + sign, 3) : std::string();
    const std::size_t end = i + sign + 3;
    if ((rest == "nan" || rest == "inf") && (end >= text.size() || !is_word_char(text[end]))) {
      const bool chinese = language == Language::Chinese;
      if (rest == "nan") out += "NaN";
      else if (text[i] == '-') out += chinese ? "负无穷大" : "-infinity";
      else out += chinese ? "无穷大" : "infinity";
      i = end;
      continue;
    }
    out += text[i++];
  }
  return out;
}
// A text as the student reads it: its numbers short (short_numbers), and every value that is not
// a number named (name_non_finite).
std::string readable(const std::string& text, Language language = Language::English) {
  return name_non_finite(short_numbers(text), language);
}
Message readable(Message message) {
  for (MessageArg& arg : message.args) {
    const std::string chinese = readable(arg.chinese_text.value_or(arg.text), Language::Chinese);
    if (arg.chinese_text || chinese != readable(arg.text)) arg.chinese_text = chinese;
    arg.text = readable(arg.text);
    for (Message& part : arg.parts) part = readable(part);
  }
  return message;
}
std::vector<Message> readable(const std::vector<Message>& messages) {
  std::vector<Message> out;
  for (const Message& message : messages) out.push_back(readable(message));
  return out;
}

// A failure's message as the test wrote it: GoogleTest 1.16 (Debian 13) appends "\n", or an OS
// stack trace after "\nStack trace:\n", to every message; 1.12 (Debian 12) appends nothing.
std::string written_message(const ::testing::TestPartResult& result) {
  std::string message = result.message();
  const std::size_t stack_trace = message.find("\nStack trace:\n");
  if (stack_trace != std::string::npos) message.erase(stack_trace);
  while (!message.empty() && message.back() == '\n') message.pop_back();
  return message;
}

// Hands each test's result to the judge's callbacks (in the judge's own process).
class Recorder : public ::testing::EmptyTestEventListener {
 public:
  Recorder(std::function<void(const std::string&)> on_start, std::function<void(const TestRecord&)> on_end)
      : on_start_(std::move(on_start)), on_end_(std::move(on_end)) {}

  void OnTestStart(const ::testing::TestInfo& info) override {
    current() = CurrentTest{};
    messages_.clear();
    not_implemented_ = false;
    blocked_by_.clear();
    blocked_function_.clear();
    stage_id_.clear();
    for (const TestInfo& test : tests())
      if (test.suite == info.test_suite_name() && test.name == info.name())
        if (const StageInfo* stage = find_stage(test.stage)) stage_id_ = stage->id;
    on_start_(full_name(info));
  }

  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (!result.failed()) return;
    const std::string message = written_message(result);
    not_implemented_ = not_implemented_ || message.find("is not implemented yet") != std::string::npos;
    // A failure the suite worded (add_failure, or failure_text after a GoogleTest check): GoogleTest
    // recorded its English after words of its own ("Failed", or "Expected equality of these
    // values: ... Which is: ..."), which the student never sees: only the worded failure, in the
    // run's language.
    std::vector<Message>& failures = current().failures;
    if (!failures.empty()) {
      std::string english = render(failures.front(), Language::English);
      while (!english.empty() && english.back() == '\n') english.pop_back();  // as written_message
      if (message.size() >= english.size() && message.compare(message.size() - english.size(), english.size(), english) == 0) {
        messages_.push_back(readable(failures.front()));
        failures.erase(failures.begin());
        return;
      }
    }
    // GoogleTest's words for an exception out of the test (the stage code's own, or the stage
    // server's "ran out of memory"): its description framed in the run's language.
    const std::string thrown = "C++ exception with description \"", in_body = "\" thrown in the test body.";
    if (message.size() >= thrown.size() + in_body.size() && message.compare(0, thrown.size(), thrown) == 0 &&
        message.compare(message.size() - in_body.size(), in_body.size(), in_body) == 0) {
      const std::string what = message.substr(thrown.size(), message.size() - thrown.size() - in_body.size());
      MessageArg described("what", cut(what));
      for (const Message& worded : current().thrown) {  // the judge's own exception: in the run's language
        if (render(worded, Language::English) != what) continue;
        described = {"what", worded};
        if (worded.id == MessageId::stage_not_implemented) {
          // A stub: of this test's stage, the sentence that says what to write; of an earlier stage
          // whose function the test runs (stage 06 grades the rounding of stage 02's sphere and
          // stage 04's box test), the test is blocked by it until it is written.
          const std::string stub_stage = argument_text(worded, "stage");
          if (stub_stage == stage_id_ || stage_id_.empty()) {
            messages_.push_back(readable(worded));
          } else {
            blocked_by_ = stub_stage;
            blocked_function_ = argument_text(worded, "function");
            Message blocked(MessageId::stage_blocked, worded.args);
            blocked.args.push_back({"current", stage_id_});
            messages_.push_back(readable(blocked));
          }
          return;
        }
      }
      messages_.push_back(readable(Message(MessageId::failure_exception, {described})));
      return;
    }
    if (message == "Unknown C++ exception thrown in the test body.") {
      messages_.push_back(MessageId::failure_unknown_exception);
      return;
    }
    messages_.push_back(verbatim(readable(cut(message))));
  }

  void OnTestEnd(const ::testing::TestInfo& info) override {
    on_end_(TestRecord{full_name(info), info.result()->Passed(), not_implemented_, messages_, readable(current().hints),
                       readable(current().notes), current().images, blocked_by_, blocked_function_,
                       readable(current().hints_if_lost)});
  }

 private:
  // A text cut at 1500 characters: a failure stays readable whatever the stage code threw.
  static std::string cut(const std::string& text) { return protocol::cut_text(text, 1500, " [...]"); }
  static std::string full_name(const ::testing::TestInfo& info) {
    return std::string(info.test_suite_name()) + "." + info.name();
  }
  // The text of a message's argument `name` ("" if it has none).
  static std::string argument_text(const Message& message, const std::string& name) {
    for (const MessageArg& arg : message.args)
      if (arg.name == name) return arg.text;
    return "";
  }
  std::function<void(const std::string&)> on_start_;
  std::function<void(const TestRecord&)> on_end_;
  std::vector<Message> messages_;
  bool not_implemented_ = false;
  std::string stage_id_;                        // the stage of the test running
  std::string blocked_by_, blocked_function_;  // an earlier stage's stub that the test ran into
};

}  // namespace

bool register_stage(const char* stage_id, std::function<void()> probe) {
  StageInfo* stage = mutable_stage(stage_id);
  if (!stage) {
    problem_registry().push_back(std::string("a suite registers the stage ") + stage_id +
                                 ", which stages.json does not list (its stages: " + stage_ids_text() + ")");
  } else if (stage->probe) {
    problem_registry().push_back(std::string("the stage ") + stage_id + " is registered twice");
  } else {
    stage->probe = std::move(probe);
  }
  return true;
}

bool register_test(const char* stage_id, const char* suite, const char* name, int points) {
  const StageInfo* stage = mutable_stage(stage_id);
  if (!stage)
    problem_registry().push_back(std::string("the test ") + suite + "." + name + " is for the stage " + stage_id +
                                 ", which stages.json does not list (its stages: " + stage_ids_text() + ")");
  test_registry().push_back({stage ? stage->number : 0, suite, name, points});
  return true;
}

const std::vector<StageInfo>& stages() { return stage_registry(); }

const StageInfo* find_stage(int number) {
  for (const StageInfo& stage : stage_registry())
    if (stage.number == number) return &stage;
  return nullptr;
}

const StageInfo* find_stage(std::string_view name) {
  const StageDescription* description = find_stage_description(name);
  return description ? mutable_stage(description->id) : nullptr;
}

std::string handout_of(const StageInfo& stage) { return stage.handout; }

std::vector<std::string> registration_problems() {
  std::vector<std::string> problems = problem_registry();
  for (const StageInfo& stage : stages()) {
    int points = 0, count = 0;
    for (const TestInfo& test : tests())
      if (test.stage == stage.number) points += test.points, ++count;
    if (!stage.probe)
      problems.push_back("no suite registers the stage " + stage.id + " (register_stage(\"" + stage.id +
                         "\", probe) in one of the files its \"suite\" lists in stages.json)");
    if (count == 0)
      problems.push_back("the stage " + stage.id + " has no GRADED_TEST");
    else if (points != stage.points)
      problems.push_back("stages.json gives the stage " + stage.id + " " + std::to_string(stage.points) +
                         " points, but its " + std::to_string(count) + " tests add up to " + std::to_string(points));
  }
  return problems;
}

const std::vector<TestInfo>& tests() { return test_registry(); }

void add_hint(const Message& hint) {
  auto& hints = current().hints;
  if (std::find(hints.begin(), hints.end(), hint) == hints.end()) hints.push_back(hint);
}

void add_note(const Message& note) { current().notes.push_back(note); }

HintIfLost::HintIfLost(const Message& hint) : exceptions_(std::uncaught_exceptions()) {
  current().hints_if_lost.push_back(hint);
}
// (A lost call throws StageLost through it: then the hint stays for the test's end to show.)
HintIfLost::~HintIfLost() {
  if (std::uncaught_exceptions() == exceptions_ && !current().hints_if_lost.empty()) current().hints_if_lost.pop_back();
}

void add_image(const ImageComparison& images) { current().images.push_back(images); }

Message not_implemented_message(const NotImplemented& e) {
  const StageDescription* description = find_stage_description(e.stage_id());
  const StageInfo* stage = find_stage(std::string_view(e.stage_id()));
  if (!description || !stage) return verbatim(e.what());
  MessageArg files("files", "assignments/" + std::string(description->files.front()));
  for (std::size_t i = 1; i < description->files.size(); ++i)
    files.parts.push_back({MessageId::stage_file_or, {{"file", "assignments/" + std::string(description->files[i])}}});
  return {MessageId::stage_not_implemented,
          {{"stage", stage->id}, {"function", e.function()}, files, {"handout", stage->handout_text}}};
}

std::string exception_text(const Message& what) {
  current().thrown.push_back(what);
  return render(what, Language::English);
}

void add_failure(const Message& failure) { ADD_FAILURE() << failure_text(failure); }

std::string failure_text(const Message& failure) {
  current().failures.push_back(failure);
  return render(failure, Language::English);
}

const std::string& output_directory() { return output_directory_storage(); }
void set_output_directory(const std::string& directory) { output_directory_storage() = directory; }

std::string reference_path(const std::string& name) { return reference_directory_storage() + "/" + name; }
void set_reference_directory(const std::string& directory) { reference_directory_storage() = directory; }

void install_recorder(std::function<void(const std::string&)> on_test_start,
                      std::function<void(const TestRecord&)> on_test_end) {
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  listeners.Append(new Recorder(std::move(on_test_start), std::move(on_test_end)));
}

}  // namespace raylab::grading
