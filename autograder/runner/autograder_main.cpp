// The autograder's entry point, shared by every variant (variant_main.cpp calls it):
// grades the stage functions of the stage code its stage server links.
//
//   autograder [--stage ID]... [--json results.json] [--output DIR] [--timeout S] [--lang en|zh] [--list]
//   autograder --list-files     the stage files of the stage table, one per line (for scripts)
//
// A stage is named by its id in stages.json or its short form: 05b_bvh_sah, 05b or 5b.
//
// It is the judge (supervisor.cpp): it runs the suites itself and never runs stage code; every
// stage function it calls is answered by a sandboxed stage server (stage_server_main.cpp,
// built as <this program>-stage-server), which links the graded stage code.
//
// It speaks English or Simplified Chinese (messages.h): --lang, else LC_ALL / LC_MESSAGES / LANG.
#include "grading.h"
#include "stage_process.h"
#include "supervisor.h"

#include "raylab/error.h"
#include "raylab/stage_table.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>

int raylab_autograder_main(int argc, char** argv, const char* description, const char* description_zh) {
  using namespace raylab::grading;
  CLI::App app{"raylab autograder: grades your stage functions against the reference"};
  SupervisorOptions options;
  options.output_directory = "grading-output";
  options.description = description;
  options.description_zh = description_zh;
  std::string language_name;
  bool list = false;
  bool list_files = false;
  std::vector<std::string> visibility_rules;
  std::vector<std::string> stage_names;
  app.add_option("--stage", stage_names,
                 "Grade only this stage: its id or short form (05b_bvh_sah, 05b or 5b); repeat for several");
  app.add_option("--json", options.json_path, "Also write a Gradescope-style results.json here");
  app.add_option("--reference", options.reference_directory,
                 "Folder of reference data (default: the checked-in autograder/reference/; a course's "
                 "own cases: autograder-regenerate --seed N --output DIR)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--output", options.output_directory, "Folder for the yours | reference | difference images")
      ->capture_default_str();
  app.add_option("--timeout", options.timeout_seconds, "Seconds a stage's code may run, all its calls together")
      ->check(CLI::Range(1.0, 3600.0))->capture_default_str();
  app.add_option("--run-timeout", options.run_timeout_seconds, "Seconds the whole grading run may take")
      ->check(CLI::Range(1.0, 86400.0))->capture_default_str();
  app.add_option("--max-processes", options.max_processes, "Processes the stage code may have at once")
      ->check(CLI::Range(1, 4096))->capture_default_str();
  app.add_option("--output-limit-kb", options.output_limit_kb, "KiB the stage code may print, per stage process")
      ->check(CLI::Range(1L, 1L << 20))->capture_default_str();
  app.add_option("--memory-mb", options.memory_limit_mb, "Memory limit per stage in MiB (0: none)")
      ->check(CLI::Range(0L, 1L << 20))->capture_default_str();
  app.add_option("--stage-server", options.server_path, "The stage server to grade (default: this program's name + -stage-server)");
  app.add_flag("--verbose", options.verbose, "Also show notes (image metrics) of passed tests");
  app.add_flag("--list", list, "List the stages and their tests, then exit");
  app.add_flag("--list-files", list_files,
               "Print the stage files of stages.json (paths under assignments/), one per line, then exit");
  app.add_option("--visibility", visibility_rules,
                 "Gradescope visibility in results.json: LEVEL for every test, or STAGE=LEVEL, or 'STAGE: Test*'=LEVEL "
                 "(* matches anything; the last rule naming a test decides); LEVEL is visible, hidden, after_due_date "
                 "or after_published");
  app.add_option("--lang", language_name,
                 "Language of the table, the failures and the hints: en or zh (default: from LC_ALL, LC_MESSAGES or "
                 "LANG; zh_CN... is Chinese)")
      ->check(CLI::IsMember({"en", "zh"}));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "autograder: " << e.what() << " (see autograder --help)\n";
    return 1;
  }
  if (!language_name.empty()) set_language(*parse_language(language_name));
  if (list_files) {
    std::vector<std::string_view> printed;
    for (const raylab::StageDescription& stage : raylab::stage_table())
      for (std::string_view file : stage.files)
        if (std::find(printed.begin(), printed.end(), file) == printed.end()) {
          printed.push_back(file);
          std::cout << file << "\n";
        }
    return 0;
  }
  for (const std::string& text : visibility_rules) {
    std::string error;
    const std::optional<VisibilityRule> rule = parse_visibility_rule(text, error);
    if (!rule) {
      std::cerr << "autograder: " << error << "\n";
      return 1;
    }
    options.visibility.push_back(*rule);
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
      std::cerr << render({MessageId::console_no_such_stage, {{"name", name}, {"stages", raylab::stage_ids_text()}}})
                << "\n";
      return 1;
    }
    options.stages.push_back(stage->number);
  }
  if (list) {
    for (const StageInfo& stage : stages()) {
      std::cout << render({MessageId::console_list_stage,
                           {{"stage", stage.id}, {"title", stage.title_text}, {"points", std::to_string(stage.points)},
                            {"handout", stage.handout_text}}})
                << "\n";
      for (const TestInfo& test : tests())
        if (test.stage == stage.number)
          std::cout << "    "
                    << render({MessageId::console_list_test, {{"test", test.name}, {"points", std::to_string(test.points)}}})
                    << "\n";
    }
    return 0;
  }
  try {
    if (options.server_path.empty())
      options.server_path = default_stage_server_path();
    return run_supervisor(options);
  } catch (const std::exception& e) {
    std::cerr << "autograder: grading could not run: " << e.what() << "\n";
    return 1;
  }
}
