// The judge: runs each stage's GoogleTest suite in its own process, where every stage function
// is a request to a sandboxed stage server (stage_call.h, stage_session.h). It never links
// stage code, decides every score from values it received, and writes the reports itself.
#pragma once

#include "gradescope.h"

#include <map>
#include <string>
#include <vector>

namespace raylab::grading {

struct SupervisorOptions {
  std::string description;         // which code is graded, for the heading
  std::string description_zh;      // the same in Chinese
  std::string server_path;         // the stage server linked with that code
  std::map<std::string, std::string> servers_for;  // stage id -> another server for that stage
                                   // (--stage-server-for; the self-tests use it)
  std::vector<int> stages;         // empty: every stage
  std::string json_path;           // Gradescope results.json, if set
  std::vector<VisibilityRule> visibility;  // Gradescope's visibility per test (gradescope.h)
  std::string output_directory;    // side-by-side images
  std::string reference_directory; // reference data ("": the checked-in autograder/reference/)
  double timeout_seconds = 60.0;   // wall clock per stage, all its calls together
  double run_timeout_seconds = 900.0;  // wall clock for the whole run
  long memory_limit_mb = 4096;     // address space of a stage server (0: no limit)
  int max_processes = 32;          // processes stage code may have at once
  long output_limit_kb = 1024;     // what stage code may print, per stage server
  int max_restarts = 3;            // fresh stage servers after a loss, per stage
  bool verbose = false;            // show passed tests' notes too
};

// Returns the process exit status: 0 when grading ran to the end, whatever the score.
int run_supervisor(const SupervisorOptions& options);

}  // namespace raylab::grading
