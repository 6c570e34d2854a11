// Autograder suite for the bonus stage 09b_mis (30 points).
//
// power_heuristic is judged against exact values, each wrong value checked against the mistakes
// that explain it. path_radiance_mis is judged twice:
//   Is it MIS? Scripted paths (09b_mis_calls.h: mis_scripted_paths): the stage server traces
//   chosen rays in a small test scene (a floor under a quad light, or under a point light) with a
//   constant sampler, so the judge knows the light point and the BSDF direction each path takes.
//   The judge computes both samples itself, with the framework's sample_li, bsdf_sample_f, pdf_li
//   and bsdf_pdf (which call the grader's own stages 07 and 08, as your path does here: stages.json,
//   "grader_versions"), and the value a correct
//   MIS path tracer returns: each sample's contribution times its power-heuristic weight. The
//   models of the common mistakes (no MIS, the balance heuristic, an area density in the weight,
//   the emission unweighted, a weighted point light, a weighted last vertex) are fitted to every
//   path: a model that explains every value is named, or two made together (mis_models.h;
//   tests/test_mis_models.cpp proves that a pair fails each test either of its mistakes fails and
//   is named there, both or, where its values are one mistake's, that one). These tests are exact
//   (float tolerance).
//   Is it unbiased? Two furnaces t-tested against their exact answer and the two Cornell boxes
//   z-tested region by region against stage 09's converged reference (path_support.h), as in
//   stage 09: an ordinary path tracer without MIS passes these and loses the scripted tests.
//
// False failures: the 2 furnace t-tests, their 2 spread tests, the test of short paths of the
// furnace with roulette (path_support.h) and the 2 x 64 x 3 region z-tests share
// kGraderFalseFailureRate (1 in 1,000 for the stage, Sidak-corrected: mis_test_level()); the
// exact tests have tolerances that a correct implementation never exceeds.
// autograder-false-failures --stage 09b_mis measures it.
#include "09b_mis_calls.h"
#include "grading.h"
#include "mis_models.h"
#include "path_support.h"
#include "support.h"

#include "raylab/error.h"
#include "raylab/stages/09b_mis.h"
#include "raylab/testkit/statistics.h"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace raylab::grading {
namespace {

using namespace mis;  // the scripted tests, power_heuristic's exact value, the models (mis_models.h)

constexpr const char* kStage = "09b_mis";
const double kLevel = mis_test_level();

// Not attempted only when both functions are the stub.
const bool kRegistered = register_stage(kStage, [] {
  throw_if_every_function_is_a_stub(
      kStage, {[] { (void)power_heuristic(1, 1.0f, 1, 1.0f); },
               [] {
                 MisScene scene;
                 scene.triangles.push_back(
                     {glm::vec3(-1, 0, -1), glm::vec3(-1, 0, 1), glm::vec3(1, 0, 0), glm::vec3(0.0f), glm::vec3(0.5f)});
                 (void)mis_scripted_paths(scene, {MisScriptedPath{glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), 0.5f,
                                                                  glm::vec2(0.5f), 0}});
               }});
});

// ---- power_heuristic -----------------------------------------------------------------------

struct HeuristicCase {
  int count_f;
  float pdf_f;
  int count_g;
  float pdf_g;
};

std::string call_text(const HeuristicCase& c) {
  return "power_heuristic(" + std::to_string(c.count_f) + ", " + gtest_text(c.pdf_f) + ", " + std::to_string(c.count_g) +
         ", " + gtest_text(c.pdf_g) + ")";
}

bool close(double got, double expected, double relative) {
  return std::fabs(got - expected) <= relative * std::fabs(expected) + 1e-7;
}

// The weights of the common mistakes, for densities f = n_f pdf_f > 0 and g = n_g pdf_g, both finite.
struct HeuristicMistake {
  MessageId hint;
  double (*weight)(const HeuristicCase&);
};
double sq(double x) { return x * x; }
const HeuristicMistake kHeuristicMistakes[] = {
    {MessageId::mis_heuristic_balance,
     [](const HeuristicCase& c) { return 1.0 * c.count_f * c.pdf_f / (1.0 * c.count_f * c.pdf_f + 1.0 * c.count_g * c.pdf_g); }},
    {MessageId::mis_heuristic_counts_ignored,
     [](const HeuristicCase& c) { return sq(c.pdf_f) / (sq(c.pdf_f) + sq(c.pdf_g)); }},
    {MessageId::mis_heuristic_counts_outside,
     [](const HeuristicCase& c) { return c.count_f * sq(c.pdf_f) / (c.count_f * sq(c.pdf_f) + c.count_g * sq(c.pdf_g)); }},
    {MessageId::mis_heuristic_other_weight,
     [](const HeuristicCase& c) { return 1.0 - exact_power(c.count_f, c.pdf_f, c.count_g, c.pdf_g); }},
};

// Checks the cases; on the first wrong value adds the failure and the hints that explain it: NaN
// from an edge case, or a mistake whose weights match every ordinary case (both densities finite,
// f's above 0) of the list.
void expect_heuristic(const std::vector<HeuristicCase>& cases) {
  std::vector<float> got;
  for (const HeuristicCase& c : cases) got.push_back(power_heuristic(c.count_f, c.pdf_f, c.count_g, c.pdf_g));
  auto ordinary = [](const HeuristicCase& c) { return c.pdf_f > 0.0f && std::isfinite(c.pdf_f) && std::isfinite(c.pdf_g); };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const HeuristicCase& c = cases[i];
    const double expected = exact_power(c.count_f, c.pdf_f, c.count_g, c.pdf_g);
    if (close(got[i], expected, 1e-5)) continue;
    add_failure({MessageId::mis_failure_value,
                 {{"call", call_text(c)}, {"got", gtest_text(got[i])}, {"expected", gtest_text(expected)}}});
    if (!std::isfinite(got[i])) {
      if (std::isinf(c.pdf_f) || std::isinf(c.pdf_g)) add_hint({MessageId::mis_heuristic_infinite, {}});
      else if (c.pdf_f == 0.0f && c.pdf_g == 0.0f) add_hint({MessageId::mis_heuristic_zero_nan, {}});
      return;
    }
    if (!ordinary(c)) return;  // an edge case: the failure says enough
    for (const HeuristicMistake& mistake : kHeuristicMistakes) {
      bool fits_all = true;
      for (std::size_t j = 0; j < cases.size() && fits_all; ++j)
        if (ordinary(cases[j])) fits_all = close(got[j], mistake.weight(cases[j]), 1e-4);
      if (fits_all) add_hint({mistake.hint, {}});
    }
    return;
  }
}

GRADED_TEST(kStage, Stage09bMis, PowerHeuristicValues, 4) {
  // The handout's worked number first (1 and 3: 0.9), then uneven densities and counts.
  expect_heuristic({{1, 3.0f, 1, 1.0f},
                    {1, 1.0f, 1, 1.0f},
                    {1, 1.0f, 1, 3.0f},
                    {1, 0.05f, 1, 0.318f},
                    {2, 1.0f, 1, 1.0f},
                    {1, 2.0f, 3, 1.0f},
                    {4, 0.25f, 1, 12.5f}});
}

GRADED_TEST(kStage, Stage09bMis, PowerHeuristicEdgeCases, 3) {
  // A density of 0 (the other strategy cannot make this sample), both 0 (0, not 0 / 0), and an
  // infinite density (a delta: only it can make the sample).
  const float infinity = std::numeric_limits<float>::infinity();
  expect_heuristic({{1, 2.0f, 1, 0.0f},
                    {1, 0.0f, 1, 2.0f},
                    {1, 0.0f, 1, 0.0f},
                    {1, infinity, 1, 0.5f},
                    {1, 0.5f, 1, infinity},
                    {1, 1e-20f, 1, 1e-20f}});
}

// ---- Scripted paths -------------------------------------------------------------------------


// Traces the paths with the student's path_radiance_mis and compares every value with the judge's;
// names the first that differs and the mistakes whose model explains every value: one, or when
// no single one does and exactly one pair does, two made together.
void expect_scripted(const ScriptedTest& test) {
  const MessageArg what = MessageArg::bilingual("what", test.english, test.chinese);
  const std::vector<MisScriptedPath> paths = scripted_paths(test.max_depth);
  const std::vector<glm::vec3> got = mis_scripted_paths(test.scene, paths);
  const std::vector<PathParts> parts = parts_of(test.scene, paths);
  for (std::size_t i = 0; i < got.size(); ++i) {
    const glm::vec3& v = got[i];
    if (hint_if_not_finite("path_radiance_mis", {v.x, v.y, v.z}, {MessageId::mis_advice_division, {}})) {
      add_failure({MessageId::mis_failure_not_finite, {what}});
      return;
    }
  }
  std::size_t wrong = got.size();
  for (std::size_t i = 0; i < got.size() && wrong == got.size(); ++i)
    if (!same_value(got[i], model_values(parts[i], MisModel{})[0])) wrong = i;
  if (wrong == got.size()) return;
  const MisScriptedPath& path = paths[wrong];
  const PathParts& p = parts[wrong];
  add_failure({MessageId::mis_failure_path,
               {what,
                {"origin", gtest_text(path.origin)},
                {"direction", gtest_text(path.direction)},
                {"u1", gtest_text(path.u1)},
                {"u2", gtest_text(path.u2)},
                {"depth", std::to_string(path.max_depth)},
                {"expected", gtest_text(glm::vec3(model_values(p, MisModel{})[0]))},
                {"got", gtest_text(got[wrong])},
                {"light", gtest_text(p.light)},
                {"light_pdf", gtest_text(p.light_pdf)},
                {"light_bsdf_pdf", gtest_text(p.bsdf_pdf_of_light)},
                {"bsdf", gtest_text(p.bsdf)},
                {"bsdf_pdf", gtest_text(p.bsdf_pdf)},
                {"bsdf_light_pdf", gtest_text(p.light_pdf_of_bsdf)}}});
  const MisFit fit = fit_mistakes(got, parts);
  if (fit.named.empty()) {
    add_hint({MessageId::mis_weights_unexplained, {}});
    return;
  }
  if (fit.together) add_hint({MessageId::mis_two_mistakes, {}});
  for (const MisMistake* mistake : fit.named) add_hint({mistake->hint, {}});
}

GRADED_TEST(kStage, Stage09bMis, LightAndBsdfSamplesWeighted, 8) {
  // A floor under a quad light: every path's light sample, and its BSDF sample when that hits the
  // light, must count with their power-heuristic weights.
  expect_scripted(scripted_tests()[0]);
}

GRADED_TEST(kStage, Stage09bMis, PointLightKeepsWeightOne, 3) {
  // No direction hits a point: its light sample is the only way to find it, weight 1.
  expect_scripted(scripted_tests()[1]);
}

GRADED_TEST(kStage, Stage09bMis, LastVertexKeepsWeightOne, 2) {
  // max_depth 0: no BSDF sample follows the camera's hit, so its light sample has weight 1.
  expect_scripted(scripted_tests()[2]);
}

// ---- Unbiased: furnaces and Cornell boxes ---------------------------------------------------

void hint_biased() { add_hint({MessageId::mis_biased, {}}); }

void expect_furnace(int index) {
  const FurnaceRender render = render_furnace(index, test_seed(200 + static_cast<std::uint64_t>(index)), true);
  if (render.not_finite) {
    add_not_finite(render.not_finite, render.pixel_count());
    return;
  }
  const double exact = furnace_exact(kFurnaces[index]);
  const testkit::MeanTestResult result = furnace_exact_test(render.pixel_means, kFurnaces[index], exact, kLevel);
  const FurnaceSpreadResult spread = furnace_spread_test(render.pixel_means, kFurnaces[index], exact, kLevel);
  std::optional<ShortPathsResult> short_paths;
  if (kFurnaces[index].roulette < 1.0)
    short_paths = furnace_short_paths_test(
        render_furnace_paths(index, test_seed(220 + static_cast<std::uint64_t>(index)), true), kFurnaces[index], kLevel);
  if (result.passed && spread.passed && (!short_paths || short_paths->passed)) return;
  if (!result.passed) add_furnace_failure(index, result);
  if (!spread.passed) add_furnace_spread_failure(index, spread, exact, kLevel);
  if (short_paths && !short_paths->passed) add_furnace_short_paths_failure(index, *short_paths, kLevel);
  if (!result.passed || !spread.passed) {
    // The emission the camera sees directly lost (weighted as if a BSDF sample had found it): every
    // path is worth 1 less, which the same t-test tells.
    if (!result.passed && furnace_mean_test(render.pixel_means, exact - 1.0, kLevel).passed)
      add_hint({MessageId::mis_camera_hit_weighted, {}});
    else
      hint_biased();
  }
}

GRADED_TEST(kStage, Stage09bMis, FurnaceWithoutRoulette, 2) { expect_furnace(0); }
GRADED_TEST(kStage, Stage09bMis, FurnaceWithRoulette, 2) { expect_furnace(1); }

void expect_cornell(int scene_index) {
  const std::optional<RegionTest> test =
      expect_cornell_matches_reference(kStage, scene_index, true, test_seed(210 + static_cast<std::uint64_t>(scene_index)),
                                       kLevel, true);
  if (test && test->failures > 0) hint_biased();
}

GRADED_TEST(kStage, Stage09bMis, CornellBoxImageMatchesReference, 3) { expect_cornell(0); }
GRADED_TEST(kStage, Stage09bMis, SpecularCornellBoxImageMatchesReference, 3) { expect_cornell(1); }

}  // namespace
}  // namespace raylab::grading
