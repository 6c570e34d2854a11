#include "supervisor.h"

#include "gradescope.h"
#include "grading.h"
#include "gtest_flags.h"
#include "report_html.h"
#include "stage_process.h"
#include "results.h"
#include "stage_session.h"

#include "raylab/error.h"
#include "raylab/stage_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

namespace raylab::grading {
namespace {

// Runs the GoogleTest suites of one stage here, in the judge; their stage calls go to the
// session's stage server.
void run_stage_tests(StageResult& result) {
  std::string filter;
  for (const TestResult& t : result.tests)
    if (filter.find(t.info.suite + ".*") == std::string::npos) filter += (filter.empty() ? "" : ":") + t.info.suite + ".*";
  GTEST_FLAG_SET(filter, filter);
  // Failures are results (recorded by the listener), not an error of the judge.
  [[maybe_unused]] const int failed = RUN_ALL_TESTS();
}

// The stage server that grades `stage`: the one --stage-server-for names, else the default
// server's path with the stage's suffix before ".exe" (a stage graded on the grader's own
// versions of earlier stages, stages.json "grader_versions", has a server of its own).
std::string server_for(const SupervisorOptions& options, const StageInfo& stage) {
  if (const auto named = options.servers_for.find(stage.id); named != options.servers_for.end()) return named->second;
  std::string path = options.server_path;
  const std::string exe = ".exe";
  const bool windows = path.size() > exe.size() && path.compare(path.size() - exe.size(), exe.size(), exe) == 0;
  path.insert(windows ? path.size() - exe.size() : path.size(), stage.server_suffix);
  return path;
}

StageResult grade_stage(const StageInfo& stage, const std::string& server_path) {
  StageResult result;
  result.stage = &stage;
  for (const TestInfo& test : tests())
    if (test.stage == stage.number) result.tests.push_back({test, Status::Lost, {MessageId::test_not_run}, {}, {}, 0.0, {}, {}, {}});

  StageSession& session = StageSession::instance();
  session.set_server_path(server_path);
  session.begin_stage();
  session.begin_test("");
  // A stub throws NotImplemented at once: the stage is not attempted, no test runs.
  std::optional<Message> not_implemented;
  try {
    if (stage.probe) stage.probe();
  } catch (const NotImplemented& e) {
    not_implemented = not_implemented_message(e);
  } catch (...) {
    // Anything else the probe meets is for the tests to find and explain.
  }
  if (not_implemented) {
    result.not_attempted = true;
    for (TestResult& t : result.tests) {
      t.status = Status::NotAttempted;
      t.messages = {*not_implemented};
    }
  } else {
    ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
    (void)listeners;
    static StageResult* recording = nullptr;
    static bool installed = false;
    static Clock::time_point test_started;
    recording = &result;
    if (!installed) {
      installed = true;
      install_recorder([](const std::string& test) {
                         test_started = Clock::now();
                         StageSession::instance().begin_test(test);
                       },
                       [](const TestRecord& record) {
                         for (TestResult& t : recording->tests) {
                           if (t.info.full_name() != record.test) continue;
                           t.seconds = std::chrono::duration<double>(Clock::now() - test_started).count();
                           if (const auto loss = StageSession::instance().test_loss()) {
                             t.status = Status::Lost;  // whatever the test concluded without the stage's answers
                             t.messages = {*loss};
                             t.hints = record.hints_if_lost;  // what the judge knows of the case it was running
                             t.notes.clear();
                             t.images.clear();
                             return;
                           }
                           t.status = record.passed            ? Status::Passed
                                      : record.not_implemented ? Status::NotAttempted
                                                               : Status::Failed;
                           t.messages = record.messages;
                           t.hints = record.hints;
                           t.notes = record.notes;
                           t.images = record.images;
                           t.blocked_by = record.blocked_by;
                           t.blocked_function = record.blocked_function;
                         }
                       });
    }
    run_stage_tests(result);
    recording = nullptr;
  }
  // Every process of the stage is gone before its results count.
  const StageEnd end = session.end_stage();
  result.problem = end.problem;
  result.output = end.output;
  return result;
}

}  // namespace

int run_supervisor(const SupervisorOptions& options) {
  const Clock::time_point run_started = Clock::now();
  std::vector<const StageInfo*> selected;
  for (const StageInfo& stage : stages())
    if (options.stages.empty() || std::find(options.stages.begin(), options.stages.end(), stage.number) != options.stages.end())
      selected.push_back(&stage);
  for (int number : options.stages)
    if (!find_stage(number)) {
      std::cerr << render({MessageId::cli_no_stage_number, {{"number", std::to_string(number)}}}) << "\n";
      return 1;
    }
  for (const StageInfo* stage : selected)
    if (!std::filesystem::exists(server_for(options, *stage))) {
      std::cerr << render({MessageId::cli_server_missing, {{"path", server_for(options, *stage)}}}) << "\n";
      return 1;
    }
  std::filesystem::create_directories(options.output_directory);
  set_output_directory(options.output_directory);
  if (!options.reference_directory.empty()) set_reference_directory(options.reference_directory);

  prepare_judge();
  SessionOptions session_options;
  session_options.server_path = options.server_path;
  session_options.limits.memory_limit_mb = options.memory_limit_mb;
  session_options.limits.max_processes = options.max_processes;
  session_options.limits.output_limit_bytes = options.output_limit_kb * 1024;
  session_options.stage_seconds = options.timeout_seconds;
  session_options.run_deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.run_timeout_seconds));
  session_options.max_restarts = options.max_restarts;
  StageSession::instance().configure(session_options);

  int gtest_argc = 1;
  char program_name[] = "autograder";
  char* gtest_argv[] = {program_name, nullptr};
  ::testing::InitGoogleTest(&gtest_argc, gtest_argv);
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  delete listeners.Release(listeners.default_result_printer());

  std::vector<StageResult> results;
  for (const StageInfo* stage : selected) {
    std::fprintf(stderr, "%s\n", render({MessageId::console_grading_stage, {{"stage", stage->id}}}).c_str());
    results.push_back(grade_stage(*stage, server_for(options, *stage)));
  }

  std::fflush(stderr);
  Message description = verbatim("");
  description.args = {MessageArg::bilingual("text", options.description, options.description_zh)};
  print_results(results, description, options.verbose);
  if (options.verbose)
    std::printf("%s\n", render({MessageId::console_sandbox, {{"how", sandbox_description()}}}).c_str());
  const std::string report = write_report_html(results, description, options.output_directory);
  std::printf("%s\n", render({MessageId::report_written, {{"path", report}}}).c_str());
  if (!options.json_path.empty()) {
    GradescopeOptions gradescope;
    gradescope.visibility = options.visibility;
    gradescope.run_seconds = std::chrono::duration<double>(Clock::now() - run_started).count();
    write_results_json(results, options.json_path, gradescope);
    std::printf("%s\n", render({MessageId::console_results_written, {{"path", options.json_path}}}).c_str());
  }
  std::fflush(stdout);
  return 0;
}

}  // namespace raylab::grading
