#include "results.h"

#include <cstdint>
#include <cstdio>
#include <sstream>

namespace raylab::grading {
namespace {

constexpr std::size_t kShownOutputBytes = 4096;
constexpr int kShownOutputLines = 40;

std::string text_of(MessageId id, std::vector<MessageArg> args = {}) { return render(Message(id, std::move(args))); }

bool is_blocked(const TestResult& t) { return t.status == Status::NotAttempted && !t.blocked_by.empty(); }

// Of a stage's tests blocked by an earlier stage's stub, one blocked by the earliest such stage
// (the one to write first), or nullptr.
const TestResult* earliest_blocked(const StageResult& stage) {
  const TestResult* earliest = nullptr;
  auto order = [](const std::string& id) {
    const StageInfo* blocking = find_stage(std::string_view(id));
    return blocking ? blocking->number : 0;
  };
  for (const TestResult& t : stage.tests)
    if (is_blocked(t) && (!earliest || order(t.blocked_by) < order(earliest->blocked_by))) earliest = &t;
  return earliest;
}

std::string status_text(const StageResult& stage) {
  if (stage.not_attempted) return text_of(MessageId::console_stage_not_attempted);
  int passed = 0, failed = 0, not_attempted = 0, blocked = 0;
  for (const TestResult& t : stage.tests) {
    passed += t.status == Status::Passed;
    failed += t.status != Status::Passed && t.status != Status::NotAttempted;
    blocked += is_blocked(t);
    not_attempted += t.status == Status::NotAttempted && !is_blocked(t);
  }
  const TestResult* first_blocked = earliest_blocked(stage);
  const std::string count = std::to_string(stage.tests.size());
  std::string text;
  if (first_blocked && blocked == static_cast<int>(stage.tests.size())) {
    // Every test runs the earlier stage's stub: what to write first, and nothing else.
    text = text_of(MessageId::console_stage_blocked,
                   {{"stage", first_blocked->blocked_by}, {"function", first_blocked->blocked_function}});
  } else {
    text = failed > 0                            ? text_of(MessageId::console_tests_failed, {{"failed", std::to_string(failed)}, {"count", count}})
           : not_attempted > 0 || blocked > 0 ? text_of(MessageId::console_tests_passed, {{"passed", std::to_string(passed)}, {"count", count}})
                                                : text_of(MessageId::console_passed);
    if (not_attempted > 0) text += text_of(MessageId::console_tests_not_attempted, {{"count", std::to_string(not_attempted)}});
    if (first_blocked)
      text += text_of(MessageId::console_tests_blocked, {{"count", std::to_string(blocked)},
                                                         {"stage", first_blocked->blocked_by},
                                                         {"function", first_blocked->blocked_function}});
  }
  if (stage.problem) text += text_of(MessageId::console_problem, {{"problem", *stage.problem}});
  return text;
}

// The columns a text takes in a terminal: a CJK character or full-width punctuation takes two.
std::size_t display_width(const std::string& text) {
  std::size_t width = 0;
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char lead = static_cast<unsigned char>(text[i]);
    const std::size_t length = lead < 0x80 ? 1 : lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
    std::uint32_t code = length == 1 ? lead : lead & (0xFF >> (length + 1));
    for (std::size_t k = 1; k < length && i + k < text.size(); ++k) code = (code << 6) | (text[i + k] & 0x3F);
    const bool wide = (code >= 0x1100 && code <= 0x115F) || (code >= 0x2E80 && code <= 0xA4CF) ||
                      (code >= 0xAC00 && code <= 0xD7A3) || (code >= 0xF900 && code <= 0xFAFF) ||
                      (code >= 0xFE30 && code <= 0xFE4F) || (code >= 0xFF00 && code <= 0xFF60) ||
                      (code >= 0xFFE0 && code <= 0xFFE6);
    width += wide ? 2 : 1;
    i += length;
  }
  return width;
}
// `text` padded with spaces to `width` columns, on the right (left-aligned) or on the left.
std::string pad_right(const std::string& text, std::size_t width) {
  const std::size_t used = display_width(text);
  return used >= width ? text : text + std::string(width - used, ' ');
}
std::string pad_left(const std::string& text, std::size_t width) {
  const std::size_t used = display_width(text);
  return used >= width ? text : std::string(width - used, ' ') + text;
}

}  // namespace

int StageResult::earned() const {
  int sum = 0;
  for (const TestResult& t : tests) sum += t.earned();
  return sum;
}

int StageResult::max() const {
  int sum = 0;
  for (const TestResult& t : tests) sum += t.info.points;
  return sum;
}

std::string stage_status(const StageResult& stage) { return status_text(stage); }

std::string test_output(const TestResult& t, Language language) {
  std::string out;
  for (const Message& m : t.messages) out += render(m, language) + "\n";
  for (const Message& h : t.hints) out += render({MessageId::console_hint, {{"hint", h}}}, language) + "\n";
  for (const Message& n : t.notes) out += render(n, language) + "\n";
  return out;
}

void print_results(const std::vector<StageResult>& results, const Message& description, bool verbose) {
  std::printf("\n%s\n\n", text_of(MessageId::console_title, {{"description", description}}).c_str());
  std::printf("  %s %s  %s\n", pad_right(text_of(MessageId::console_stage), 22).c_str(),
              pad_left(text_of(MessageId::console_points), 9).c_str(), text_of(MessageId::console_status).c_str());
  int earned = 0, max = 0;
  for (const StageResult& stage : results) {
    std::printf("  %-22s %4d/%-4d  %s\n", stage.stage->id.c_str(), stage.earned(), stage.max(), status_text(stage).c_str());
    earned += stage.earned();
    max += stage.max();
  }
  std::printf("  %s %4d/%-4d\n", pad_right(text_of(MessageId::console_total), 22).c_str(), earned, max);

  for (const StageResult& stage : results) {
    if (stage.not_attempted) continue;
    bool header = false;
    for (const TestResult& t : stage.tests) {
      // A passed test is shown when it has advice (a hint that costs no points) or, with
      // --verbose, notes.
      const bool show = t.status != Status::Passed || !t.hints.empty() || (verbose && !t.notes.empty());
      if (!show) continue;
      if (!header) {
        std::printf("\n%s\n", text_of(MessageId::console_failures_header,
                                       {{"stage", stage.stage->id}, {"title", stage.stage->title_text},
                                        {"handout", stage.stage->handout_text}})
                                   .c_str());
        header = true;
      }
      const MessageId label = t.status == Status::Passed         ? MessageId::console_label_passed
                              : t.status == Status::Lost         ? MessageId::console_label_lost
                              : t.status == Status::NotAttempted ? MessageId::console_label_not_attempted
                                                                 : MessageId::console_label_failed;
      std::printf("  %s %s%s\n", pad_right(text_of(label), 6).c_str(), t.info.name.c_str(),
                  text_of(t.info.points == 1 ? MessageId::console_test_point : MessageId::console_test_points, {{"points", std::to_string(t.info.points)}}).c_str());
      std::istringstream lines(test_output(t, language()));
      for (std::string line; std::getline(lines, line);) std::printf("         %s\n", shown_as_text(line).c_str());
    }
  }

  bool header = false;
  for (const StageResult& stage : results) {
    if (stage.output.empty()) continue;
    if (!header) {
      std::printf("\n%s\n", text_of(MessageId::console_output_header).c_str());
      header = true;
    }
    std::printf("  %s:\n", stage.stage->id.c_str());
    std::istringstream lines(stage.output.substr(0, kShownOutputBytes));
    int shown = 0;
    for (std::string line; std::getline(lines, line) && shown < kShownOutputLines; ++shown)
      std::printf("    | %s\n", shown_as_text(line).c_str());
    if (stage.output.size() > kShownOutputBytes || shown == kShownOutputLines)
      std::printf("    %s\n", text_of(MessageId::console_output_cut, {{"bytes", std::to_string(stage.output.size())}}).c_str());
  }
  std::printf("\n");
  if (const Message* next = next_step(results)) std::printf("%s\n", text_of(MessageId::console_next, {{"what", *next}}).c_str());
}

const Message* next_step(const std::vector<StageResult>& results) {
  for (const StageResult& stage : results) {
    if (stage.not_attempted && !stage.tests.empty() && !stage.tests.front().messages.empty())
      return &stage.tests.front().messages.front();
    if (stage.not_attempted) continue;
    const TestResult* blocked = earliest_blocked(stage);
    if (blocked && !blocked->messages.empty()) return &blocked->messages.front();
  }
  return nullptr;
}

}  // namespace raylab::grading
