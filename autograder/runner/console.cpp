#include "results.h"

#include <cstdio>
#include <sstream>

namespace raylab::grading {
namespace {

constexpr std::size_t kShownOutputBytes = 4096;
constexpr int kShownOutputLines = 40;

std::string status_text(const StageResult& stage) {
  if (stage.not_attempted) return "not attempted";
  int failed = 0, not_attempted = 0;
  for (const TestResult& t : stage.tests) {
    failed += t.status != Status::Passed && t.status != Status::NotAttempted;
    not_attempted += t.status == Status::NotAttempted;
  }
  std::string text = failed == 0 ? "passed" : std::to_string(failed) + " of " + std::to_string(stage.tests.size()) + " tests failed";
  if (not_attempted > 0) text += "; " + std::to_string(not_attempted) + " tests not attempted (a function still a stub)";
  if (!stage.problem.empty()) text += "; " + stage.problem;
  return text;
}

// Printable: control characters (escape sequences that could move the cursor or rewrite the
// table above) become '?'.
std::string printable(const std::string& line) {
  std::string text;
  for (const char c : line) text += (static_cast<unsigned char>(c) < 32 && c != '\t') || c == 127 ? '?' : c;
  return text;
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

std::string test_output(const TestResult& t) {
  std::string out;
  for (const std::string& m : t.messages) out += m + "\n";
  for (const std::string& h : t.hints) out += "hint: " + h + "\n";
  for (const std::string& n : t.notes) out += n + "\n";
  return out;
}

void print_results(const std::vector<StageResult>& results, const std::string& description, bool verbose) {
  std::printf("\nraylab autograder: %s\n\n", description.c_str());
  std::printf("  %-22s %9s  %s\n", "stage", "points", "status");
  int earned = 0, max = 0;
  for (const StageResult& stage : results) {
    std::printf("  %-22s %4d/%-4d  %s\n", stage.stage->id.c_str(), stage.earned(), stage.max(), status_text(stage).c_str());
    earned += stage.earned();
    max += stage.max();
  }
  std::printf("  %-22s %4d/%-4d\n", "total", earned, max);

  for (const StageResult& stage : results) {
    if (stage.not_attempted) continue;
    bool header = false;
    for (const TestResult& t : stage.tests) {
      const bool show = t.status != Status::Passed || (verbose && !t.notes.empty());
      if (!show) continue;
      if (!header) {
        std::printf("\n%s: %s (handout: %s)\n", stage.stage->id.c_str(), stage.stage->title.c_str(),
                    handout_of(*stage.stage).c_str());
        header = true;
      }
      const char* label = t.status == Status::Passed         ? "passed"
                          : t.status == Status::Lost         ? "LOST"
                          : t.status == Status::NotAttempted ? "not attempted:"
                                                             : "FAILED";
      std::printf("  %-6s %s (%d points)\n", label, t.info.name.c_str(), t.info.points);
      std::istringstream lines(test_output(t));
      for (std::string line; std::getline(lines, line);) std::printf("         %s\n", printable(line).c_str());
    }
  }

  bool header = false;
  for (const StageResult& stage : results) {
    if (stage.output.empty()) continue;
    if (!header) {
      std::printf("\nyour program's output (printed by your stage code; it does not change the scores above):\n");
      header = true;
    }
    std::printf("  %s:\n", stage.stage->id.c_str());
    std::istringstream lines(stage.output.substr(0, kShownOutputBytes));
    int shown = 0;
    for (std::string line; std::getline(lines, line) && shown < kShownOutputLines; ++shown)
      std::printf("    | %s\n", printable(line).c_str());
    if (stage.output.size() > kShownOutputBytes || shown == kShownOutputLines)
      std::printf("    (%zu bytes in all; the rest is not shown)\n", stage.output.size());
  }
  std::printf("\n");
  for (const StageResult& stage : results)
    if (stage.not_attempted && !stage.tests.empty() && !stage.tests.front().messages.empty()) {
      std::printf("next: %s\n", stage.tests.front().messages.front().c_str());
      break;
    }
}

}  // namespace raylab::grading
