// The judge's results: what each test earned, and how the score table and results.json show it.
#pragma once

#include "grading.h"

#include <string>
#include <vector>

namespace raylab::grading {

enum class Status { Passed, Failed, NotAttempted, Lost };

struct TestResult {
  TestInfo info;
  Status status = Status::Lost;
  std::vector<std::string> messages, hints, notes;
  int earned() const { return status == Status::Passed ? info.points : 0; }
};

struct StageResult {
  const StageInfo* stage = nullptr;
  std::vector<TestResult> tests;
  std::string problem;  // crash / time-out, for the table
  bool not_attempted = false;
  std::string output;   // what the stage code printed (never parsed, only shown)
  int earned() const;
  int max() const;
};

// A test's messages, hints and notes, one per line.
std::string test_output(const TestResult& test);

// console.cpp: the score table, then the failures with their hints, then the stage code's
// own output, set apart.
void print_results(const std::vector<StageResult>& results, const std::string& description, bool verbose);

// results_json.cpp: Gradescope's results.json, written to a fresh temporary file beside `path`
// and renamed over it, so nothing another process wrote there first survives.
void write_results_json(const std::vector<StageResult>& results, const std::string& path);

}  // namespace raylab::grading
