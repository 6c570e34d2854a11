// The autograder's entry point, shared by every variant (variant_main.cpp calls it):
// grades the stage functions it is linked with.
//
//   autograder [--stage ID]... [--json results.json] [--output DIR] [--timeout S] [--list]
//
// A stage is named by its id in stages.json or its short form: 05b_bvh_sah, 05b or 5b.
//
// Without --child it is the supervisor (supervisor.cpp): it runs itself once per stage with
// --child, under a time and memory limit, and never calls stage code. With --child it runs
// one stage's GoogleTest suite and reports each test to the supervisor through a file.
#include "grading.h"
#include "supervisor.h"

#include "raylab/error.h"
#include "raylab/stage_table.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace {

using namespace raylab::grading;

std::vector<int> parse_stage_list(const std::string& text) {
  std::vector<int> numbers;
  if (text == "none") return numbers;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) numbers.push_back(std::stoi(item));
  return numbers;
}

void report_not_implemented(const std::string& report_path, const std::string& message) {
  const std::string line = nlohmann::json{{"event", "not_implemented"}, {"message", message}}.dump() + "\n";
  const int fd = ::open(report_path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd >= 0) {
    [[maybe_unused]] const ssize_t written = ::write(fd, line.data(), line.size());
    ::close(fd);
  }
}

int run_child(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);  // takes --gtest_filter
  int stage_number = 0;
  std::string report_path, output_directory = "grading-output", incomplete = "none";
  for (int i = 1; i + 1 < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--child") stage_number = std::atoi(argv[++i]);
    else if (arg == "--report") report_path = argv[++i];
    else if (arg == "--output") output_directory = argv[++i];
    else if (arg == "--incomplete") incomplete = argv[++i];
  }
  const StageInfo* stage = find_stage(stage_number);
  if (!stage || report_path.empty()) {
    std::cerr << "autograder: bad --child invocation\n";
    return 1;
  }
  set_output_directory(output_directory);
  set_incomplete_dependencies(parse_stage_list(incomplete));
  // A stub throws NotImplemented at once: report the stage as not attempted, run nothing.
  try {
    if (stage->probe) stage->probe();
  } catch (const raylab::NotImplemented& e) {
    report_not_implemented(report_path, e.what());
    return 0;
  } catch (...) {
    // Anything else the probe throws is for the tests to find and explain.
  }
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  delete listeners.Release(listeners.default_result_printer());
  install_reporter(report_path);
  // Failures are results (already reported), not an error of the child.
  [[maybe_unused]] const int failed = RUN_ALL_TESTS();
  return 0;
}

}  // namespace

int raylab_autograder_main(int argc, char** argv, const char* description) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--child") == 0) return run_child(argc, argv);

  CLI::App app{"raylab autograder: grades your stage functions against the reference"};
  SupervisorOptions options;
  options.output_directory = "grading-output";
  options.description = description;
  bool list = false;
  std::vector<std::string> stage_names;
  app.add_option("--stage", stage_names,
                 "Grade only this stage: its id or short form (05b_bvh_sah, 05b or 5b); repeat for several");
  app.add_option("--json", options.json_path, "Also write a Gradescope-style results.json here");
  app.add_option("--output", options.output_directory, "Folder for the yours | reference | difference images")
      ->capture_default_str();
  app.add_option("--timeout", options.timeout_seconds, "Seconds a stage may run before it is stopped")
      ->check(CLI::Range(1.0, 3600.0))->capture_default_str();
  app.add_option("--memory-mb", options.memory_limit_mb, "Memory limit per stage in MiB (0: none)")
      ->check(CLI::Range(0L, 1L << 20))->capture_default_str();
  app.add_flag("--verbose", options.verbose, "Also show notes (image metrics) of passed tests");
  app.add_flag("--list", list, "List the stages and their tests, then exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "autograder: " << e.what() << " (see autograder --help)\n";
    return 1;
  }
  const std::vector<std::string> problems = registration_problems();
  if (!problems.empty()) {
    std::cerr << "autograder: the suites and stages.json disagree (the grader's bug, not yours):\n";
    for (const std::string& problem : problems) std::cerr << "  " << problem << "\n";
    return 1;
  }
  for (const std::string& name : stage_names) {
    const StageInfo* stage = find_stage(std::string_view(name));
    if (!stage) {
      std::cerr << "autograder: there is no stage \"" << name << "\"; the stages are " << raylab::stage_ids_text()
                << " (or their short forms, e.g. 05b)\n";
      return 1;
    }
    options.stages.push_back(stage->number);
  }
  if (list) {
    for (const StageInfo& stage : stages()) {
      std::cout << stage.id << ": " << stage.title << " (" << stage.points << " points; handout: " << stage.handout
                << ")\n";
      for (const TestInfo& test : tests())
        if (test.stage == stage.number) std::cout << "    " << test.name << " (" << test.points << " points)\n";
    }
    return 0;
  }
  try {
    return run_supervisor(std::filesystem::canonical("/proc/self/exe").string(), options);
  } catch (const std::exception& e) {
    std::cerr << "autograder: grading could not run: " << e.what() << "\n";
    return 1;
  }
}
