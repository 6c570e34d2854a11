#include "supervisor.h"

#include "grading.h"

#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace raylab::grading {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

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
  std::string problem;  // crash / time-out / not attempted, for the table
  bool not_attempted = false;
  int earned() const {
    int sum = 0;
    for (const TestResult& t : tests) sum += t.earned();
    return sum;
  }
  int max() const {
    int sum = 0;
    for (const TestResult& t : tests) sum += t.info.points;
    return sum;
  }
};

std::string signal_description(int signal_number) {
  const char* name = ::strsignal(signal_number);
  std::string text = "signal " + std::to_string(signal_number);
  if (name) text += " (" + std::string(name) + ")";
  if (signal_number == SIGSEGV) text += ": your code read or wrote memory it does not own (an index out of range? a null pointer?)";
  else if (signal_number == SIGFPE) text += ": an integer division by zero?";
  else if (signal_number == SIGABRT) text += ": abort(), a failed assert or an uncaught exception";
  else if (signal_number == SIGKILL || signal_number == SIGXCPU) text += ": killed, probably over the memory or time limit";
  return text;
}

struct ChildOutcome {
  bool timed_out = false;
  bool signalled = false;
  int signal_number = 0;
  int exit_code = 0;
};

ChildOutcome run_child(const std::vector<std::string>& arguments, const SupervisorOptions& options) {
  std::vector<char*> argv;
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::cout.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (pid == 0) {
    ::setpgid(0, 0);  // its own process group: a time-out kills every thread and child it made
    if (options.memory_limit_mb > 0) {
      const rlim_t bytes = static_cast<rlim_t>(options.memory_limit_mb) * 1024 * 1024;
      const struct rlimit limit{bytes, bytes};
      ::setrlimit(RLIMIT_AS, &limit);
    }
    const struct rlimit no_core{0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core);
    ::execv(argv[0], argv.data());
    std::perror("autograder: exec failed");
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  ChildOutcome outcome;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options.timeout_seconds);
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      outcome.timed_out = true;
      return outcome;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(-pid, SIGKILL);  // anything the child left behind in its group
  if (WIFSIGNALED(status)) {
    outcome.signalled = true;
    outcome.signal_number = WTERMSIG(status);
  } else if (WIFEXITED(status)) {
    outcome.exit_code = WEXITSTATUS(status);
  }
  return outcome;
}

struct Report {
  bool not_implemented = false;
  std::string not_implemented_message;
  std::string running;  // started, never ended
  std::map<std::string, json> ended;
};

Report read_report(const fs::path& path) {
  Report report;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    json event = json::parse(line, nullptr, false);
    if (event.is_discarded() || !event.is_object()) continue;  // a line cut by a crash
    const std::string kind = event.value("event", "");
    if (kind == "not_implemented") {
      report.not_implemented = true;
      report.not_implemented_message = event.value("message", "");
    } else if (kind == "start") {
      report.running = event.value("test", "");
    } else if (kind == "end") {
      const std::string test = event.value("test", "");
      report.ended[test] = event;
      if (report.running == test) report.running.clear();
    }
  }
  return report;
}

StageResult grade_stage(const StageInfo& stage, const std::string& self_path, const SupervisorOptions& options,
                        const std::vector<int>& incomplete, const fs::path& work_directory) {
  StageResult result;
  result.stage = &stage;
  for (const TestInfo& test : tests())
    if (test.stage == stage.number) result.tests.push_back({test, Status::Lost, {}, {}, {}});

  std::set<std::string> settled;  // tests with a final result
  std::string incomplete_list;
  for (int s : incomplete) incomplete_list += (incomplete_list.empty() ? "" : ",") + std::to_string(s);

  for (int attempt = 0; attempt <= options.max_resumes; ++attempt) {
    std::string filter;
    std::set<std::string> suites;
    for (const TestResult& t : result.tests) suites.insert(t.info.suite);
    for (const std::string& suite : suites) filter += (filter.empty() ? "" : ":") + suite + ".*";
    std::string excluded;
    for (const std::string& name : settled) excluded += (excluded.empty() ? "" : ":") + name;
    if (!excluded.empty()) filter += "-" + excluded;

    const fs::path report_path = work_directory / ("stage" + std::to_string(stage.number) + "-" + std::to_string(attempt) + ".jsonl");
    fs::remove(report_path);
    const ChildOutcome outcome = run_child(
        {self_path, "--child", std::to_string(stage.number), "--report", report_path.string(), "--output",
         options.output_directory, "--incomplete", incomplete_list.empty() ? "none" : incomplete_list,
         "--gtest_filter=" + filter},
        options);
    const Report report = read_report(report_path);

    if (report.not_implemented) {
      result.not_attempted = true;
      result.problem = "not attempted";
      for (TestResult& t : result.tests) {
        t.status = Status::NotAttempted;
        t.messages = {report.not_implemented_message};
      }
      return result;
    }
    for (TestResult& t : result.tests) {
      const auto it = report.ended.find(t.info.full_name());
      if (it == report.ended.end()) continue;
      const json& event = it->second;
      t.status = event.value("passed", false) ? Status::Passed
                 : event.value("not_implemented", false) ? Status::NotAttempted : Status::Failed;
      t.messages = event.value("messages", std::vector<std::string>{});
      t.hints = event.value("hints", std::vector<std::string>{});
      t.notes = event.value("notes", std::vector<std::string>{});
      settled.insert(t.info.full_name());
    }

    const bool all_reported = settled.size() == result.tests.size();
    if (all_reported && !outcome.timed_out && !outcome.signalled) return result;

    // The child ended early. Name the test it was in; decide whether to go on without it.
    std::string reason;
    if (outcome.timed_out) {
      std::ostringstream text;
      text << "timed out after " << options.timeout_seconds << " s (an endless loop?)";
      reason = text.str();
    } else if (outcome.signalled) {
      reason = "crashed with " + signal_description(outcome.signal_number);
    } else {
      reason = "the program exited (status " + std::to_string(outcome.exit_code) +
               ") in the middle of grading: do not call exit() in stage code";
    }
    const std::string where = report.running.empty() ? "before its first test" : "in " + report.running;
    result.problem = reason + ", " + where;
    for (TestResult& t : result.tests) {
      if (settled.count(t.info.full_name())) continue;
      if (t.info.full_name() == report.running) {
        t.status = Status::Lost;
        t.messages = {reason + " during this test"};
        settled.insert(t.info.full_name());
      }
    }
    const bool can_resume = !outcome.timed_out && !report.running.empty() && attempt < options.max_resumes;
    if (!can_resume) {
      for (TestResult& t : result.tests)
        if (!settled.count(t.info.full_name())) {
          t.status = Status::Lost;
          t.messages = {"not run: the stage's process " + reason + " " + where};
        }
      return result;
    }
  }
  return result;
}

std::string status_text(const StageResult& stage) {
  if (stage.not_attempted) return "not attempted";
  int failed = 0;
  for (const TestResult& t : stage.tests) failed += t.status != Status::Passed;
  std::string text = failed == 0 ? "passed" : std::to_string(failed) + " of " + std::to_string(stage.tests.size()) + " tests failed";
  if (!stage.problem.empty()) text += "; " + stage.problem;
  return text;
}

std::string test_output(const TestResult& t) {
  std::string out;
  for (const std::string& m : t.messages) out += m + "\n";
  for (const std::string& h : t.hints) out += "hint: " + h + "\n";
  for (const std::string& n : t.notes) out += n + "\n";
  return out;
}

void print_results(const std::vector<StageResult>& results, const SupervisorOptions& options) {
  std::printf("\nraylab autograder: %s\n\n", options.description.c_str());
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
      const bool show = t.status != Status::Passed || (options.verbose && !t.notes.empty());
      if (!show) continue;
      if (!header) {
        std::printf("\n%s: %s (handout: %s)\n", stage.stage->id.c_str(), stage.stage->title.c_str(),
                    handout_of(*stage.stage).c_str());
        header = true;
      }
      const char* label = t.status == Status::Passed ? "passed" : t.status == Status::Lost ? "LOST" : "FAILED";
      std::printf("  %-6s %s (%d points)\n", label, t.info.name.c_str(), t.info.points);
      std::istringstream lines(test_output(t));
      for (std::string line; std::getline(lines, line);) std::printf("         %s\n", line.c_str());
    }
  }
  std::printf("\n");
  for (const StageResult& stage : results)
    if (stage.not_attempted && !stage.tests.empty() && !stage.tests.front().messages.empty()) {
      std::printf("next: %s\n", stage.tests.front().messages.front().c_str());
      break;
    }
}

void write_json(const std::vector<StageResult>& results, const std::string& path) {
  json tests_json = json::array();
  int earned = 0, max = 0;
  for (const StageResult& stage : results)
    for (const TestResult& t : stage.tests) {
      tests_json.push_back({{"name", stage.stage->id + ": " + t.info.name},
                            {"score", t.earned()},
                            {"max_score", t.info.points},
                            {"output", test_output(t)},
                            {"visibility", "visible"}});
      earned += t.earned();
      max += t.info.points;
    }
  const json results_json = {{"score", earned}, {"max_score", max}, {"tests", tests_json}};
  std::ofstream out(path);
  out << results_json.dump(2) << "\n";
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace

int run_supervisor(const std::string& self_path, const SupervisorOptions& options) {
  std::vector<const StageInfo*> selected;
  for (const StageInfo& stage : stages())
    if (options.stages.empty() || std::find(options.stages.begin(), options.stages.end(), stage.number) != options.stages.end())
      selected.push_back(&stage);
  for (int number : options.stages)
    if (!find_stage(number)) {
      std::cerr << "autograder: there is no stage " << number << " (see autograder --list)\n";
      return 1;
    }
  fs::create_directories(options.output_directory);
  const fs::path work_directory = fs::temp_directory_path() / ("raylab-grading-" + std::to_string(::getpid()));
  fs::create_directories(work_directory);

  std::vector<StageResult> results;
  std::map<int, bool> complete;  // stage number -> full marks
  for (const StageInfo* stage : selected) {
    std::vector<int> incomplete;
    for (int dependency : stage->depends_on)
      if (complete.count(dependency) && !complete[dependency]) incomplete.push_back(dependency);
    std::fprintf(stderr, "grading %s ...\n", stage->id.c_str());
    results.push_back(grade_stage(*stage, self_path, options, incomplete, work_directory));
    complete[stage->number] = results.back().earned() == results.back().max();
  }
  fs::remove_all(work_directory);

  print_results(results, options);
  if (!options.json_path.empty()) {
    write_json(results, options.json_path);
    std::printf("results written to %s\n", options.json_path.c_str());
  }
  return 0;
}

}  // namespace raylab::grading
