// Helpers shared by the stage suites and the regenerate tool.
#pragma once

#include "raylab/bounds.h"
#include "raylab/image.h"
#include "raylab/ray.h"
#include "raylab/random.h"
#include "raylab/scene.h"
#include "raylab/testkit/random_values.h"
#include "messages.h"
#include "stage_image.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace raylab::grading {

// Random test values come from the kit's one generator, raylab::Pcg32 (raylab/random.h),
// with a stream per purpose (testkit::stream_of) and the helpers of raylab/testkit/random_values.h.
// Draw one value per statement (or in a braced list): the order in which a function's
// arguments are evaluated differs between compilers, and the cases must not.

// The probe of a stage of several functions (register_stage's): makes each call, and throws the
// first NotImplemented of `stage_id` only when every call threw one, so that the stage is "not
// attempted" while all its functions are stubs (and each test of a written function is graded).
// A stub of another stage that a call goes through is that stage's to report: not counted.
void throw_if_every_function_is_a_stub(const char* stage_id, std::initializer_list<std::function<void()>> calls);

// The first check of every stage's diagnosis: when one of the student's `results` is not a
// number, adds the hint "returns NaN (<what> = NaN): <advice>" (or "returns infinity") and
// returns true, so no later hint reads a NaN as a wrong number ("a hit behind the ray").
// Failure texts need nothing: the grader prints every non-finite value as NaN or infinity.
bool hint_if_not_finite(const std::string& what, std::initializer_list<float> results, const Message& advice);
bool hint_if_not_finite(const Message& what, std::initializer_list<float> results, const Message& advice);

// A value as GoogleTest's message stream writes it (17 significant digits): the format of a value in
// a failure text, as when it was streamed into ADD_FAILURE() itself. The student reads it short:
// the judge shows every number of a failure, hint or note as the shortest text of the same float
// (messages.h: short_numbers), 0.3 and not 0.30000001192092896.
template <typename Value>
std::string gtest_text(const Value& value) {
  return (::testing::Message() << value).GetString();
}

// A ray ("origin (0, 0, 5) direction (0, 0, 1) t in (0, infinity)", as the framework's operator<<
// writes it, numbers as gtest_text) and a box ("[(-1, -1, -1) .. (1, 1, 1)]" or "[empty]") for
// failure texts and hints, in the run's language.
Message ray_text(const Ray& ray);
Message box_text(const Bounds3& box);

// "t = <t>" (the stream's format, or std::to_string's with `fixed`) or "no hit", for failure texts.
Message hit_text(std::optional<float> t, bool fixed = false);

nlohmann::json to_json(const glm::vec3& v);
glm::vec3 vec3_from_json(const nlohmann::json& value);

// The checked-in reference cases of a stage: autograder/reference/<stage_id>_cases.json.
nlohmann::json load_reference_cases(const std::string& stage_id);

// How autograder-regenerate makes a stage's reference data: `generate` returns the fields of
// autograder/reference/<stage_id>_cases.json besides "stage" and "seed", computed with the
// solutions it is linked with. Every stage gets the same seed and draws from its own stream,
// Pcg32(seed, testkit::stream_of(stage_id)), so adding a stage changes no other stage's cases. A stage's <id>_cases.cpp registers it:
//   const bool kRegistered = register_reference_data("02_sphere", {sphere_cases});
struct ReferenceData {
  std::function<nlohmann::json(std::uint32_t seed)> generate;
  bool seeded = true;  // false: the data does not depend on the seed ("seed": null)
};
bool register_reference_data(const char* stage_id, ReferenceData data);
// The registered generator of a stage, or nullptr.
const ReferenceData* reference_data_of(const std::string& stage_id);

// The seed of a Monte Carlo test's random numbers (stages 08, 09 and 09b): `graded_seed` whenever a
// student is graded (round 0), another independent seed in each later round. Only
// autograder-false-failures sets a round: it grades the reference again and again to count how
// often a correct program fails by bad luck. A suite that caches a result keys it by the seed.
std::uint64_t test_seed(std::uint64_t graded_seed);
// How many of the values at the same index differ bit for bit (a NaN equals the same NaN): what a
// deterministic function asked twice must not give. Only the indices both lists have are compared.
std::size_t bitwise_differences(const std::vector<glm::vec3>& first, const std::vector<glm::vec3>& second);
void set_test_seed_round(std::uint64_t round);

std::string reference_image_name(const std::string& stage_id);  // "<id>.png"
// The seed a case file names, as its failures show it: the released data's number, or "private"
// for a course's fresh cases (autograder-regenerate --seed).
std::string seed_shown(const nlohmann::json& case_file);

// The image test: renders the stage's picture with the linked stage code, compares it with
// the reference (both as 8-bit sRGB PNG, so quantisation is the same), writes
// <output>/<stage_id>.png = yours | reference | difference (and each of the three on its own,
// <stage_id>-yours.png, -reference.png, -difference.png, for the HTML report), and fails when
// more than max_fraction of the pixels differ by more than channel_threshold.
void expect_image_matches_reference(const std::string& stage_id, float channel_threshold, double max_fraction);

struct ImageComparison;  // grading.h
// A traced pixel of a failing picture (raylab/trace.h), shown under the picture in the report, and
// a note naming its first disagreement (or saying it has none) with `command`, which prints the
// same trace on the student's machine.
void attach_pixel_trace(ImageComparison& images, PixelTrace trace, const std::string& command);

}  // namespace raylab::grading
