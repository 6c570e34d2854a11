// Autograder suite for stage 09_path (40 points).
//
// path_radiance runs in the stage server, which renders whole pictures with it (09_path_calls.h:
// path_render) and returns each pixel's mean and variance of the mean; the judge decides.
//   Furnaces (scenes/furnace.json, a sphere seen from inside, emitting 1 with albedo a): every
//   pixel's expectation is known exactly, sum over the vertices a path reaches of a^k (see
//   path_models.h). A t-test of the pixel means against it (forgiving 0.1%: kFurnaceTolerance),
//   at three (albedo, roulette probability, max depth). When a test fails, models of the common
//   mistakes (roulette not divided by p, emission counted twice, the light black when seen
//   directly, the cosine or 1 / pi missing, no direct light at all: a shadow ray that hits the
//   light itself) are fitted to all three furnaces: a model that fits all of them is named.
//   Cornell boxes (scenes/cornell.json, scenes/cornell_specular.json), kCornellSize pixels
//   square at kStudentSamples spp, against a converged reference (autograder/reference/
//   09_path_cases.json): per region of 4x4 pixels and channel a z-test of the mean, with the
//   larger of the student's and the reference's variance (so a correct strategy of higher
//   variance passes too), and a picture of the z-scores.
//
//   A t-test cannot reject a wrong estimator whose weights grow along the path (1 / pi missing,
//   with roulette): its spread is as huge as its mean. So each furnace's pixels must also spread
//   no more than a correct path tracer's can (path_support.h: furnace_spread_test, by Markov's
//   inequality from a bound on the variance of every correct variant).
//   And code that does no work earns nothing: a furnace with roulette also fails when too few of
//   its paths end early with little light, as Russian roulette makes a correct path tracer's
//   (path_support.h: furnace_short_paths_test, an exact binomial bound). A constant, or a path
//   tracer that never plays the roulette, fails it.
//   The paths sample with the grader's own stages 07 and 08 (stages.json: "grader_versions"), so
//   a failing test here is this stage's own mistake.
//
// False failures: the 3 furnace t-tests, their 3 spread tests, the 2 tests of short paths and the
// 2 x 64 x 3 region z-tests share kGraderFalseFailureRate (1 in 1,000 for the stage, Sidak-corrected);
// autograder-path-false-failures (autograder/tools/path_false_failures.cpp) measures it over
// many seeds.
#include "grading.h"
#include "path_models.h"
#include "path_support.h"
#include "support.h"

#include "raylab/error.h"
#include "raylab/image.h"
#include "raylab/math.h"
#include "raylab/testkit/statistics.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <utility>
#include <optional>
#include <string>
#include <vector>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "09_path";
const double kLevel = path_test_level();

// Not attempted when path_radiance is the stub (it runs on the grader's own stages 07 and 08,
// never stubs).
const bool kRegistered = register_stage(kStage, [] {
  PathRenderRequest request;
  request.probe_only = 1;
  (void)path_render("scenes/furnace.json", request);
});

// ---- Furnaces ------------------------------------------------------------------------------

const FurnaceRender& furnace_render(int index) {
  static std::map<std::pair<int, std::uint64_t>, FurnaceRender> cache;  // by (furnace, seed)
  const std::uint64_t seed = test_seed(100 + static_cast<std::uint64_t>(index));
  const auto found = cache.find({index, seed});
  if (found != cache.end()) return found->second;
  return cache.emplace(std::make_pair(index, seed), render_furnace(index, seed, false)).first->second;
}

bool fits(const PathModel& model, int index) {
  const FurnaceRender& render = furnace_render(index);
  if (render.not_finite || render.pixel_means.size() < 2) return false;
  return furnace_mean_test(render.pixel_means, furnace_value(model, kFurnaces[index]), kLevel).passed;
}

// Whether the furnaces fit the correct model changed by `made` (one mistake, or two together).
bool fits(const std::vector<const PathMistake*>& made) {
  const PathModel model = path_model_with(made);
  bool wild = false;
  for (const PathMistake* mistake : made) wild = wild || mistake->wild_weights;
  for (int i = 0; i < kFurnaceCount; ++i) {
    if (!wild) {
      if (!fits(model, i)) return false;
      continue;
    }
    if (kFurnaces[i].roulette < 1.0) continue;
    const FurnaceRender& render = furnace_render(i);
    if (render.not_finite || render.pixel_means.size() < 2) return false;
    const double predicted = furnace_value(model, kFurnaces[i]);
    const testkit::MeanTestResult result = furnace_mean_test(render.pixel_means, predicted, kLevel);
    if (!(std::fabs(result.mean - predicted) <= std::max(0.1 * predicted, 4.0 * result.standard_error))) return false;
  }
  return true;
}

// The test of short paths (path_support.h: furnace_short_paths_test) of a furnace with roulette;
// nullopt for the one without.
const std::optional<ShortPathsResult>& furnace_short_paths(int index) {
  static std::map<std::pair<int, std::uint64_t>, std::optional<ShortPathsResult>> cache;  // by (furnace, seed)
  const std::uint64_t seed = test_seed(300 + static_cast<std::uint64_t>(index));
  const auto found = cache.find({index, seed});
  if (found != cache.end()) return found->second;
  std::optional<ShortPathsResult> result;
  if (kFurnaces[index].roulette < 1.0)
    result = furnace_short_paths_test(render_furnace_paths(index, seed, false), kFurnaces[index], kLevel);
  return cache.emplace(std::make_pair(index, seed), result).first->second;
}

// A furnace is right when its pixels pass the t-test of their mean, the test of their spread
// (path_support.h: furnace_spread_test) and, with roulette, the test of short paths.
bool furnace_right(int index) {
  const FurnaceRender& render = furnace_render(index);
  if (render.not_finite || render.pixel_means.size() < 2) return false;
  const double exact = furnace_exact(kFurnaces[index]);
  const std::optional<ShortPathsResult>& short_paths = furnace_short_paths(index);
  return furnace_exact_test(render.pixel_means, kFurnaces[index], exact, kLevel).passed &&
         furnace_spread_test(render.pixel_means, kFurnaces[index], exact, kLevel).passed &&
         (!short_paths || short_paths->passed);
}

// The hints of a failing test: the fitted models of the furnaces that fit; true when any does.
// Tame models (finite variance: a t-test of every furnace) before wild ones (fitted on fewer
// furnaces and more loosely: PathMistake), and within each, one mistake before two made together:
// a pair is named (both) when no single mistake fits and exactly one pair does (two pairs that fit
// alike cannot be told apart). So an exact fit of two tame mistakes is not mistaken for a loose fit
// of one wild one.
bool hint_mistakes() {
  const std::vector<PathMistake>& all = path_mistakes();
  for (const bool wild : {false, true}) {
    bool any = false;
    for (const PathMistake& mistake : all)
      if (mistake.wild_weights == wild && fits({&mistake})) {
        add_hint({mistake.hint, {}});
        any = true;
      }
    if (any) return true;
    std::vector<std::pair<const PathMistake*, const PathMistake*>> fitting;
    for (std::size_t i = 0; i < all.size(); ++i)
      for (std::size_t j = i + 1; j < all.size(); ++j)
        if ((all[i].wild_weights || all[j].wild_weights) == wild && fits({&all[i], &all[j]}))
          fitting.emplace_back(&all[i], &all[j]);
    if (fitting.empty()) continue;
    if (fitting.size() > 1) return false;
    add_hint({MessageId::path_two_mistakes, {}});
    add_hint({fitting[0].first->hint, {}});
    add_hint({fitting[0].second->hint, {}});
    return true;
  }
  return false;
}

void expect_furnace(int index) {
  const FurnaceRender& render = furnace_render(index);
  if (render.not_finite) {
    add_not_finite(render.not_finite, render.pixel_count());
    return;
  }
  const double exact = furnace_exact(kFurnaces[index]);
  const testkit::MeanTestResult result = furnace_exact_test(render.pixel_means, kFurnaces[index], exact, kLevel);
  const FurnaceSpreadResult spread = furnace_spread_test(render.pixel_means, kFurnaces[index], exact, kLevel);
  const std::optional<ShortPathsResult>& short_paths = furnace_short_paths(index);
  if (result.passed && spread.passed && (!short_paths || short_paths->passed)) return;
  if (!result.passed) add_furnace_failure(index, result);
  if (!spread.passed) add_furnace_spread_failure(index, spread, exact, kLevel);
  if (short_paths && !short_paths->passed) add_furnace_short_paths_failure(index, *short_paths, kLevel);
  if (!result.passed || !spread.passed) hint_mistakes();
}

GRADED_TEST(kStage, Stage09Path, FurnaceWithoutRoulette, 8) { expect_furnace(0); }
GRADED_TEST(kStage, Stage09Path, FurnaceWithRoulette, 8) { expect_furnace(1); }
GRADED_TEST(kStage, Stage09Path, FurnaceLowAlbedo, 6) { expect_furnace(2); }

// ---- Where nothing is hit ------------------------------------------------------------------

GRADED_TEST(kStage, Stage09Path, BackgroundWhereNothingIsHit, 1) {
  // One path from the Cornell box's camera, looking away from the box: it hits nothing, so it
  // brings the scene's background, here not black (every graded picture has a black one).
  PathRenderRequest request;
  request.probe_only = 1;
  request.probe_away = 1;
  request.background = glm::vec3(0.25f, 0.5f, 0.75f);
  request.seed = test_seed(140);
  const glm::vec3 got = path_render("scenes/cornell.json", request).mean.at(0, 0);
  if (got == request.background) return;
  add_failure({MessageId::path_failure_background,
               {{"got", gtest_text(got)}, {"expected", gtest_text(request.background)}}});
}

GRADED_TEST(kStage, Stage09Path, SameSeedSamePicture, 1) {
  // Every random number from the sampler: a small picture rendered twice with one seed is the
  // same, bit for bit (path_support.h: repeat_test).
  const RepeatResult repeat = repeat_test(test_seed(130));
  if (repeat.differing > 0) add_repeat_failure(repeat);
}

// ---- Cornell boxes -------------------------------------------------------------------------

// Whether the plain box (scene 0) matched its reference, once its test has run.
std::optional<bool>& plain_box_passed() {
  static std::optional<bool> passed;
  return passed;
}

void expect_cornell(int scene_index) {
  const std::optional<RegionTest> test =
      expect_cornell_matches_reference(kStage, scene_index, false, test_seed(kStudentSeed), kLevel);
  const bool passed = test && test->failures == 0;
  if (scene_index == 0) plain_box_passed() = passed;
  if (!test || passed) return;
  // The furnaces name the mistake when they can.
  if (hint_mistakes()) return;
  bool furnaces_right = true;
  for (int i = 0; i < 3 && furnaces_right; ++i) furnaces_right = furnace_right(i);
  if (!furnaces_right) return;
  // Right furnaces: the weights along a path are right. What a furnace cannot show: a ray started
  // too close to the surface it leaves for the box's coordinates (the furnace is a unit sphere,
  // which a small fixed offset clears); and, in the specular box only, what happens after mirrors
  // and glass (no furnace has them).
  if (scene_index == 0)
    add_hint({MessageId::path_ray_starts_on_surface, {}});
  else if (plain_box_passed().value_or(false))
    add_hint({MessageId::path_specular_wrong, {}});
}

GRADED_TEST(kStage, Stage09Path, CornellBoxImageMatchesReference, 8) { expect_cornell(0); }
GRADED_TEST(kStage, Stage09Path, SpecularCornellBoxImageMatchesReference, 8) { expect_cornell(1); }

}  // namespace
}  // namespace raylab::grading
