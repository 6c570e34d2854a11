// raylab's error types: one per kind of failure. Only main() turns them into exit codes.
#pragma once

#include <stdexcept>
#include <string>

namespace raylab {

struct StageDescription;

// A stage function that the student has not written yet. Stubs throw it with the function's
// name; the message names its stage, file and handout from the stage table (stages.json).
// The renderer exits with status 2 and the autograder reports the stage as "not attempted".
class NotImplemented : public std::logic_error {
 public:
  explicit NotImplemented(const std::string& function);
  const std::string& stage_id() const { return stage_id_; }
  const std::string& function() const { return function_; }

 private:
  NotImplemented(const std::string& function, const StageDescription& stage);
  std::string stage_id_, function_;
};

// Bad input in a file (scene JSON or mesh OBJ): the message names the file, the place
// (JSON path or line) and what was expected.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad command-line usage.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Exit statuses of every raylab program (documented in README.md).
enum ExitStatus : int { kExitOk = 0, kExitBadInput = 1, kExitNotImplemented = 2 };

}  // namespace raylab
