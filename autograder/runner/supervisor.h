// The autograder's supervisor: grades stages in child processes and reports the scores.
// It never calls stage code itself.
#pragma once

#include <string>
#include <vector>

namespace raylab::grading {

struct SupervisorOptions {
  std::string description;        // which code is graded, for the heading
  std::vector<int> stages;        // empty: every stage
  std::string json_path;          // Gradescope results.json, if set
  std::string output_directory;   // side-by-side images
  double timeout_seconds = 60.0;  // wall clock, per child process
  long memory_limit_mb = 4096;    // address space of a child (0: no limit)
  int max_resumes = 3;            // after a crash, continue past the crashed test this often
  bool verbose = false;           // show passed tests' notes too
};

// Returns the process exit status: 0 when grading ran to the end, whatever the score.
int run_supervisor(const std::string& self_path, const SupervisorOptions& options);

}  // namespace raylab::grading
