// The autograder's entry point, shared by every variant (variant_main.cpp calls it):
// grades the stage functions of the stage code its stage server links.
//
//   autograder [--stage ID]... [--json results.json] [--output DIR] [--timeout S] [--lang en|zh] [--list]
//   autograder --list-files     the stage files of the stage table, one per line (for scripts)
//   autograder --compile-failed BUILD_LOG --json results.json
//                               results.json for a submission that did not compile (run_autograder)
//
// A stage is named by its id in stages.json or its short form: 05b_bvh_sah, 05b or 5b.
//
// It is the judge (supervisor.cpp): it runs the suites itself and never runs stage code; every
// stage function it calls is answered by a sandboxed stage server (stage_server_main.cpp,
// built as <this program>-stage-server), which links the graded stage code.
//
// It speaks English or Simplified Chinese (messages.h): --lang, else LC_ALL / LC_MESSAGES / LANG.
#include "grading.h"
#include "results.h"
#include "stage_process.h"
#include "supervisor.h"

#include "raylab/error.h"
#include "raylab/stage_table.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <new>
#include <optional>
#include <string_view>

namespace {

// The stage files (under `stage_folder`, e.g. <kit>/assignments) changed after `server` (the stage
// server, which links them) was built: a build that failed, or none since the edit, leaves the
// old stage server, which grades the old code. Files that cannot be read are left out.
std::vector<std::string> stage_files_newer_than(const std::filesystem::path& server,
                                                const std::filesystem::path& stage_folder) {
  std::vector<std::string> newer;
  std::error_code error;
  const auto built = std::filesystem::last_write_time(server, error);
  if (error) return newer;
  for (const raylab::StageDescription& stage : raylab::stage_table())
    for (std::string_view file : stage.files) {
      const std::filesystem::path path = stage_folder / std::string(file);
      const auto written = std::filesystem::last_write_time(path, error);
      if (error || written <= built) continue;
      const std::string shown = (stage_folder.filename() / std::string(file)).generic_string();
      if (std::find(newer.begin(), newer.end(), shown) == newer.end()) newer.push_back(shown);
    }
  return newer;
}

}  // namespace

int raylab_autograder_main(int argc, char** argv, const char* description, const char* description_zh,
                           const char* stage_folder) {
  using namespace raylab::grading;
  // --help and the options' descriptions in the run's language: --lang, read before the
  // options are parsed, else the environment. (CLI11's own words in an error stay English.)
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    std::optional<Language> chosen;
    if (arg == "--lang" && i + 1 < argc) chosen = parse_language(argv[i + 1]);
    else if (arg.substr(0, 7) == "--lang=") chosen = parse_language(arg.substr(7));
    if (chosen) set_language(*chosen);
  }
  auto worded = [](MessageId id) { return render(id); };
  CLI::App app{worded(MessageId::cli_description)};
  app.get_formatter()->label("Usage", worded(MessageId::cli_label_usage));
  app.get_formatter()->label("OPTIONS", worded(MessageId::cli_label_options_placeholder));
  app.option_defaults()->group(worded(MessageId::cli_label_options));
  app.set_help_flag("-h,--help", worded(MessageId::cli_help));
  SupervisorOptions options;
  options.output_directory = "grading-output";
  options.description = description;
  options.description_zh = description_zh;
  std::string language_name;
  bool list = false;
  bool list_files = false;
  std::string compile_failed_log;
  std::vector<std::string> visibility_rules;
  std::vector<std::string> servers_for;
  std::vector<std::string> stage_names;
  app.add_option("--stage", stage_names,
                 worded(MessageId::cli_stage));
  app.add_option("--json", options.json_path, worded(MessageId::cli_json));
  app.add_option("--reference", options.reference_directory,
                 worded(MessageId::cli_reference))
      ->check(CLI::ExistingDirectory);
  app.add_option("--output", options.output_directory, worded(MessageId::cli_output))
      ->capture_default_str();
  app.add_option("--timeout", options.timeout_seconds, worded(MessageId::cli_timeout))
      ->check(CLI::Range(1.0, 3600.0))->capture_default_str();
  app.add_option("--run-timeout", options.run_timeout_seconds, worded(MessageId::cli_run_timeout))
      ->check(CLI::Range(1.0, 86400.0))->capture_default_str();
  app.add_option("--max-processes", options.max_processes, worded(MessageId::cli_max_processes))
      ->check(CLI::Range(1, 4096))->capture_default_str();
  app.add_option("--output-limit-kb", options.output_limit_kb, worded(MessageId::cli_output_limit))
      ->check(CLI::Range(1L, 1L << 20))->capture_default_str();
  app.add_option("--memory-mb", options.memory_limit_mb, worded(MessageId::cli_memory))
      ->check(CLI::Range(0L, 1L << 20))->capture_default_str();
  long judge_memory_mb = 4096;
  app.add_option("--judge-memory-mb", judge_memory_mb, worded(MessageId::cli_judge_memory))
      ->check(CLI::Range(0L, 1L << 20))->capture_default_str();
  app.add_option("--stage-server", options.server_path, worded(MessageId::cli_stage_server));
  app.add_option("--stage-server-for", servers_for, worded(MessageId::cli_stage_server_for));
  app.add_flag("--verbose", options.verbose, worded(MessageId::cli_verbose));
  app.add_flag("--list", list, worded(MessageId::cli_list));
  app.add_flag("--list-files", list_files,
               worded(MessageId::cli_list_files));
  app.add_option("--compile-failed", compile_failed_log, worded(MessageId::cli_compile_failed));
  app.add_option("--visibility", visibility_rules,
                 worded(MessageId::cli_visibility));
  app.add_option("--lang", language_name,
                 worded(MessageId::cli_lang))
      ->check(CLI::IsMember({"en", "zh"}));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << render({MessageId::cli_usage_error, {{"error", e.what()}}}) << "\n";
    return 1;
  }
  if (!language_name.empty()) set_language(*parse_language(language_name));
  if (!compile_failed_log.empty()) {
    if (options.json_path.empty()) {
      std::cerr << render({MessageId::cli_usage_error, {{"error", "--compile-failed needs --json"}}}) << "\n";
      return 1;
    }
    try {
      write_compile_failure_json(compile_failed_log, options.json_path);
    } catch (const std::exception& e) {
      std::cerr << render({MessageId::cli_could_not_run, {{"error", e.what()}}}) << "\n";
      return 1;
    }
    return 0;
  }
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
  for (const std::string& text : servers_for) {
    const std::size_t equals = text.find('=');
    const StageInfo* stage = equals == std::string::npos ? nullptr : find_stage(std::string_view(text).substr(0, equals));
    if (!stage || equals + 1 == text.size()) {
      std::cerr << render({MessageId::cli_stage_server_for_malformed, {{"text", text}, {"stages", raylab::stage_ids_text()}}})
                << "\n";
      return 1;
    }
    options.servers_for[stage->id] = text.substr(equals + 1);
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
                    << render({test.points == 1 ? MessageId::console_list_test_one_point : MessageId::console_list_test, {{"test", test.name}, {"points", std::to_string(test.points)}}})
                    << "\n";
    }
    return 0;
  }
  // The judge's own memory is bounded, and running out of it is the grader's failure, never a
  // test's: the message is made now, while there is memory, and written as it is when new fails.
  static std::string out_of_memory;
  out_of_memory = render({MessageId::judge_out_of_memory, {{"limit", std::to_string(judge_memory_mb)}}}) + "\n";
  std::set_new_handler([] {
    std::fwrite(out_of_memory.data(), 1, out_of_memory.size(), stderr);  // (stderr has no buffer to allocate)
    std::_Exit(3);
  });
  limit_judge_memory(judge_memory_mb);
  try {
    if (options.server_path.empty())
      options.server_path = default_stage_server_path();
    if (stage_folder) {
      const std::vector<std::string> newer = stage_files_newer_than(options.server_path, stage_folder);
      if (!newer.empty()) {
        std::string files;
        for (const std::string& file : newer) files += (files.empty() ? "" : ", ") + file;
        std::cerr << render({MessageId::cli_stage_code_newer, {{"files", files}}}) << "\n";
      }
    }
    return run_supervisor(options);
  } catch (const std::exception& e) {
    std::cerr << render({MessageId::cli_could_not_run, {{"error", e.what()}}}) << "\n";
    return 1;
  }
}
