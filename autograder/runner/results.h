// The judge's results: what each test earned, and how the score table and results.json show it.
#pragma once

#include "grading.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab::grading {

enum class Status { Passed, Failed, NotAttempted, Lost };

struct TestResult {
  TestInfo info;
  Status status = Status::Lost;
  std::vector<Message> messages;  // what went wrong (an assertion's text is verbatim(), English)
  std::vector<Message> hints;
  std::vector<Message> notes;
  double seconds = 0;  // wall clock from the test's start to its end, in the judge
  std::vector<ImageComparison> images;  // for the HTML report
  std::string blocked_by, blocked_function;  // NotAttempted: an earlier stage's stub it ran into (TestRecord)
  int earned() const { return status == Status::Passed ? info.points : 0; }
};

struct StageResult {
  const StageInfo* stage = nullptr;
  std::vector<TestResult> tests;
  std::optional<Message> problem;  // crash / time-out, for the table (stage_session.h)
  bool not_attempted = false;
  std::string output;   // what the stage code printed (never parsed, only shown)
  int earned() const;
  int max() const;
};

// The stage's status as the score table shows it ("passed", "2 of 5 tests failed; ...").
std::string stage_status(const StageResult& stage);

// What to do next, for the line "next: ..." under the score table: the first stage (in the table's
// order) that is not attempted, its stub's sentence; or that has tests blocked by an earlier
// stage's stub, the blocked sentence. nullptr when there is none.
const Message* next_step(const std::vector<StageResult>& results);

// A test's messages, hints and notes, one per line, in `language`.
std::string test_output(const TestResult& test, Language language);

// console.cpp: the score table, then the failures with their hints, then the stage code's
// own output, set apart.
// In this run's language (messages.h); `description` names what is graded, in either language.
void print_results(const std::vector<StageResult>& results, const Message& description, bool verbose);

struct GradescopeOptions;  // gradescope.h

// results_json.cpp: Gradescope's results.json (English; each test's hints also as ids with their
// English and Chinese texts; Markdown output, visibility, times and a leaderboard: gradescope.h),
// written to a fresh temporary file beside `path` and renamed over it, so nothing another
// process wrote there first survives.
void write_results_json(const std::vector<StageResult>& results, const std::string& path, const GradescopeOptions& options);
// Writes `text` to `path` the same way: a fresh temporary file beside it, renamed over it.
// Throws std::runtime_error naming the file if it cannot.
void replace_file(const std::string& path, const std::string& text);

// results.json for a submission that did not compile (tools/gradescope/run_autograder): score 0,
// and the compiler's first error lines from `build_log` (at most 20, each cut at 300 bytes), shown
// as text (an indented code block of shown_as_text lines), in English and Chinese. Written with
// the JSON library, so it is valid whatever the log holds.
void write_compile_failure_json(const std::string& build_log, const std::string& path);

}  // namespace raylab::grading
