// The autograder's vocabulary, used by the per-stage suites in autograder/suites/.
//
// A stage registers itself (id, title, the stages it builds on, and a probe that calls one of
// its functions so that a stub's NotImplemented is seen at once). A graded test is a
// GoogleTest TEST with points; inside it, add_hint() names a common mistake that the test
// recognised, so the student reads "picture upside down: ..." next to the failure.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace raylab::grading {

struct StageInfo {
  int number = 0;
  std::string id;                // "01_camera_rays": folder, handout and suite share it
  std::string title;
  std::string handout;           // "docs/<id>.md" when empty
  std::vector<int> depends_on;   // earlier stages its image test renders with
  std::function<void()> probe;   // calls the stage's function(s) once; a stub throws
};

bool register_stage(StageInfo stage);
bool register_test(int stage, const char* suite, const char* name, int points);

const std::vector<StageInfo>& stages();
const StageInfo* find_stage(int number);
std::string handout_of(const StageInfo& stage);

struct TestInfo {
  int stage;
  std::string suite, name;
  int points;
  std::string full_name() const { return suite + "." + name; }
};
const std::vector<TestInfo>& tests();

// Inside a test: a hint for the student, shown with the failure (deduplicated).
void add_hint(const std::string& hint);
// Inside a test: a note shown with the result whether it passes or not (e.g. image metrics).
void add_note(const std::string& note);

// Where image tests write yours | reference | difference pictures.
const std::string& output_directory();
void set_output_directory(const std::string& directory);

// autograder/reference/<name>: the checked-in reference data.
std::string reference_path(const std::string& name);

// Child side: reports each test's start and end to `report_path` (one JSON object per line,
// written before the next test starts, so a crash loses nothing already reported).
void install_reporter(const std::string& report_path);

// The verdict of a stage's earlier stages, passed by the supervisor to the child, so that an
// image test can say "this picture uses your stage 1, which is not complete".
void set_incomplete_dependencies(const std::vector<int>& stage_numbers);
bool dependency_incomplete(int stage_number);
// For an image test: hint naming earlier stages that are incomplete, if any.
void hint_about_dependencies(int stage_number);

}  // namespace raylab::grading

#define RAYLAB_GRADING_CONCAT2(a, b) a##b
#define RAYLAB_GRADING_CONCAT(a, b) RAYLAB_GRADING_CONCAT2(a, b)

// A graded test: GRADED_TEST(1, Stage01CameraRays, CentreRayPointsAtLookAt, 3) { ... }
#define GRADED_TEST(stage, suite, name, points)                                          \
  static const bool RAYLAB_GRADING_CONCAT(suite##_##name##_registered_, __LINE__) =       \
      ::raylab::grading::register_test(stage, #suite, #name, points);                     \
  TEST(suite, name)
