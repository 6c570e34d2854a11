// The autograder's vocabulary, used by the per-stage suites in autograder/suites/.
//
// The stages are the rows of stages.json (raylab/stage_table.h): their id, title, handout,
// the stages they need and their points come from there. A suite registers its stage's probe
// by id (a call of one of its functions, so that a stub's NotImplemented is seen at once). A
// graded test is a GoogleTest TEST with points, which must add up to the table's points for
// the stage; inside it, add_hint() names a common mistake that the test recognised, so the
// student reads "picture upside down: ..." next to the failure. A hint is a Message: an id of the
// catalogue (messages.def: English and Chinese) with its values (messages.h).
#pragma once

#include "messages.h"

#include "raylab/error.h"
#include "raylab/trace.h"

#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raylab::grading {

// One row of the stage table, as the grader uses it.
struct StageInfo {
  int number = 0;                // 1 + its row in stages.json: internal (the judge's key),
                                 // never shown; users see the id
  std::string id;                // "05b_bvh_sah"
  std::string title;             // "bonus: binned SAH build"
  std::string handout;           // "docs/05_bvh.md, section 5"
  std::string handout_file;      // "docs/05_bvh.md"
  std::string handout_file_zh;   // "docs/zh/05_bvh.md", its Chinese twin
  Message title_text{MessageId::verbatim};    // the title in either language ("附加题：分桶 SAH 构建")
  Message handout_text{MessageId::verbatim};  // the handout in either language ("docs/zh/05_bvh.md，第 5 节")
  std::string server_suffix;     // its stage server is the default one's path + this (before
                                 // ".exe"): "-with-grader-07-08" ("grader_versions"), or ""
  int points = 0;                // what stages.json says its tests add up to
  std::function<void()> probe;   // calls the stage's function(s) once; a stub throws
};

// A suite's registration of its stage's probe; stage_id is a row of stages.json.
bool register_stage(const char* stage_id, std::function<void()> probe);
bool register_test(const char* stage_id, const char* suite, const char* name, int points);

// Every stage of the table, in its order.
const std::vector<StageInfo>& stages();
const StageInfo* find_stage(int number);
// By id, short id or short id without leading zeros ("05b_bvh_sah", "05b", "5b").
const StageInfo* find_stage(std::string_view name);
std::string handout_of(const StageInfo& stage);

// Where the suites and the table disagree (a registration for a stage the table lacks, a
// stage without a probe or tests, points that do not add up to the table's): one sentence
// each. The autograder refuses to grade while there are any.
std::vector<std::string> registration_problems();

struct TestInfo {
  int stage;
  std::string suite, name;
  int points;
  std::string full_name() const { return suite + "." + name; }
};
const std::vector<TestInfo>& tests();

// Inside a test: a hint for the student, shown with the failure (deduplicated). A hint is an entry
// of messages.def: add_hint({MessageId::sphere_hit_behind, {{"t", std::to_string(t)}}}).
void add_hint(const Message& hint);
// Inside a test, while it lives: the hint to show if the stage is lost (a crash, a time-out) during
// the calls it covers. A lost test shows only why it was lost; the judge knows which case it was
// running, which the student's crashed code cannot say:
//   { const HintIfLost hint(MessageId::direct_estimate_no_lights); samples = direct_light_samples(...); }
class HintIfLost {
 public:
  explicit HintIfLost(const Message& hint);
  ~HintIfLost();
  HintIfLost(const HintIfLost&) = delete;
  HintIfLost& operator=(const HintIfLost&) = delete;

 private:
  int exceptions_;  // in flight when it began: more at its end means a call threw through it
};
// Inside a test: a failure whose text is an entry of messages.def. GoogleTest records it in English;
// the judge shows it in this run's language. (A plain GoogleTest failure is shown as it is.)
void add_failure(const Message& failure);
// The same for an assertion's message, which GoogleTest evaluates only when the assertion fails:
// EXPECT_EQ(failures, 0) << failure_text({MessageId::..., {...}}). Returns the English text.
std::string failure_text(const Message& failure);
// The text of an exception that the judge throws out of a test (what the stage code threw,
// rebuilt from the stage server's reply: its stub's "not implemented", running out of memory).
// Returns the English, for the exception's what(); GoogleTest's failure for it is shown in the
// run's language.
std::string exception_text(const Message& what);
// "stage 01_camera_rays is not implemented yet: write generate_camera_ray in
// assignments/01_camera_rays/camera_rays.cpp (handout: docs/01_camera_rays.md)", in either
// language: the same sentence as NotImplemented's own (framework/src/error.cpp).
Message not_implemented_message(const NotImplemented& e);
// Inside a test: a note shown with the result whether it passes or not (e.g. image metrics), an
// entry of messages.def like a hint.
void add_note(const Message& note);

// Inside a test: pictures to compare, shown side by side (and with a slider between the student's
// and the expected one) in the HTML report, grading-output/index.html (report_html.h). Files in
// output_directory(), named without the folder; `difference` may be "" (none).
struct ImageComparison {
  std::string yours, reference, difference;
  Message yours_label{MessageId::report_yours};
  Message reference_label{MessageId::report_reference};
  Message difference_label{MessageId::report_difference};
  // A failing picture's pixel that differs most, traced through the stage code
  // (stage_image.h: trace_stage_image_pixel), and the command that shows it on the student's
  // machine; nullopt where there is none.
  std::optional<PixelTrace> worst_pixel{};
  std::string trace_command{};
};
void add_image(const ImageComparison& images);

// Where image tests write yours | reference | difference pictures.
const std::string& output_directory();
void set_output_directory(const std::string& directory);

// <reference directory>/<name>: the reference data, by default the checked-in
// autograder/reference/; a course grading with its own private seed sets the folder it
// regenerated (autograder --reference DIR, after autograder-regenerate --seed N --output DIR).
std::string reference_path(const std::string& name);
void set_reference_directory(const std::string& directory);

// What one test found, as the judge's GoogleTest listener saw it.
struct TestRecord {
  std::string test;  // "Suite.Name"
  bool passed = false;
  bool not_implemented = false;  // a failure message is a stub's NotImplemented
  std::vector<Message> messages;
  std::vector<Message> hints;
  std::vector<Message> notes;
  std::vector<ImageComparison> images;
  // The stub was an earlier stage's ("04_box"), whose function the test runs (stage 06 grades the
  // rounding of stage 04's box test), and the function it ran into: the test is blocked by that
  // stage, not failed by its own ("" when the stub, if any, is the test's own stage's).
  std::string blocked_by, blocked_function;
  std::vector<Message> hints_if_lost;  // HintIfLost's, of the calls running when the test ended
};
// The judge: calls on_test_start before each test and on_test_end after it.
void install_recorder(std::function<void(const std::string&)> on_test_start,
                      std::function<void(const TestRecord&)> on_test_end);


}  // namespace raylab::grading

#define RAYLAB_GRADING_CONCAT2(a, b) a##b
#define RAYLAB_GRADING_CONCAT(a, b) RAYLAB_GRADING_CONCAT2(a, b)

// A graded test: GRADED_TEST("01_camera_rays", Stage01CameraRays, CentreRayPointsAtLookAt, 3) { ... }
#define GRADED_TEST(stage, suite, name, points)                                          \
  static const bool RAYLAB_GRADING_CONCAT(suite##_##name##_registered_, __LINE__) =       \
      ::raylab::grading::register_test(stage, #suite, #name, points);                     \
  TEST(suite, name)
