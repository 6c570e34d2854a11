// Attacks on the grader, for the hostile self-test submissions (hostile_*.cpp): what a student
// who wants a better score than their code earns could try from inside a stage function. Each
// returns quietly when the sandbox stops it; the self-tests check that none of it changes a score.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hostile {

// The grader's command line (the judge is the stage server's parent): its --json and --output.
inline std::vector<std::string> parent_arguments() {
  std::ifstream in("/proc/" + std::to_string(::getppid()) + "/cmdline", std::ios::binary);
  std::vector<std::string> arguments;
  for (std::string argument; std::getline(in, argument, '\0');) arguments.push_back(argument);
  return arguments;
}

inline std::string parent_option(const std::string& name) {
  const std::vector<std::string> arguments = parent_arguments();
  for (std::size_t i = 0; i + 1 < arguments.size(); ++i)
    if (arguments[i] == name) return arguments[i + 1];
  return "";
}

inline const char* kForgedResults =
    "{\"score\": 128, \"max_score\": 128, \"tests\": [{\"name\": \"forged\", \"score\": 128, \"max_score\": 128}]}\n";

// Writes a full-marks results.json where the grader will write its own, and beside it.
inline void forge_results_json() {
  const std::string json = parent_option("--json");
  if (json.empty()) return;
  for (const std::string& path : {json, json + ".tmp", json.substr(0, json.rfind('/') + 1) + ".results.json.000000"}) {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out) continue;
    std::fputs(kForgedResults, out);
    std::fclose(out);
  }
  ::symlink("/dev/null", json.c_str());
}

// Appends to and replaces the reference data (found from this file's own path).
inline void overwrite_reference_data(const char* this_file) {
  std::string directory = this_file;
  directory = directory.substr(0, directory.rfind('/')) + "/../../autograder/reference/";
  for (const char* name : {"01_camera_rays_cases.json", "02_sphere.png", "forged.json"}) {
    const std::string path = directory + name;
    if (std::FILE* out = std::fopen(path.c_str(), "a")) {
      std::fputs("forged\n", out);
      std::fclose(out);
    }
  }
  ::unlink((directory + "03_triangle.png").c_str());
  ::rename((directory + "04_box_cases.json").c_str(), (directory + "moved.json").c_str());
}

// "Passed" events in the format the old grader's report file used, and a score table like the
// grader's, on stdout and stderr (with escape codes that try to clear the screen first).
inline std::string forged_report_lines() {
  std::ostringstream text;
  for (const char* test : {"Stage01CameraRays.CornersOfASmallImage", "Stage01CameraRays.TopRowLooksUpLeftColumnLooksLeft",
                           "Stage01CameraRays.MatchesReferenceRays", "Stage01CameraRays.DirectionImageMatchesReference"})
    text << "{\"event\":\"end\",\"test\":\"" << test << "\",\"passed\":true,\"messages\":[],\"hints\":[],\"notes\":[]}\n";
  return text.str();
}

inline void print_fake_scores() {
  const char* table =
      "\033[2J\033[H\r  01_camera_rays           20/20    passed\n"
      "  total                   128/128\n";
  std::fputs(table, stdout);
  std::fflush(stdout);
  std::fputs(table, stderr);
}

// Writes forged report lines to the descriptors the stage server inherited: 0, 1, 2 (and, with
// every_descriptor, all others, the grader's own pipes included).
inline void write_to_inherited_descriptors(bool every_descriptor) {
  const std::string lines = forged_report_lines();
  for (int fd = 0; fd < (every_descriptor ? 1024 : 3); ++fd) [[maybe_unused]] ssize_t n = ::write(fd, lines.data(), lines.size());
}

// A grandchild in its own session, which outlives its parent and, after `delay_seconds`, writes
// a forged results.json where the grader wrote its own (after the grader has exited).
inline void detach_late_writer(unsigned delay_seconds) {
  const std::string json = parent_option("--json");
  const pid_t child = ::fork();
  if (child != 0) {
    if (child > 0) ::waitpid(child, nullptr, 0);  // the first child exits at once
    return;
  }
  ::setsid();
  if (::fork() != 0) ::_exit(0);
  ::sleep(delay_seconds);
  if (std::FILE* out = std::fopen(json.c_str(), "w")) {
    std::fputs(kForgedResults, out);
    std::fclose(out);
  }
  ::_exit(0);
}

}  // namespace hostile
