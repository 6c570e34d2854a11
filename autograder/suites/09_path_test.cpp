// Autograder suite for stage 09_path (40 points).
//
// path_radiance runs in the stage server, which renders whole pictures with it (09_path_calls.h:
// path_render) and returns each pixel's mean and variance of the mean; the judge decides.
//   Furnaces (scenes/furnace.json, a sphere seen from inside, emitting 1 with albedo a): every
//   pixel's expectation is known exactly, sum over the vertices a path reaches of a^k (see
//   furnace_model). A t-test of the pixel means against it (forgiving 0.1%: kFurnaceTolerance),
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
//   The paths sample with the grader's own stages 07 and 08 (stages.json: "grader_versions"), so
//   a failing test here is this stage's own mistake.
//
// False failures: the 3 furnace t-tests, their 3 spread tests and the 2 x 64 x 3 region z-tests
// share
// kGraderFalseFailureRate (1 in 1,000 for the stage, Sidak-corrected);
// autograder-path-false-failures (autograder/tools/path_false_failures.cpp) measures it over
// many seeds.
#include "grading.h"
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
constexpr double kPiD = 3.14159265358979323846;
const double kLevel = path_test_level();

// Not attempted when path_radiance is the stub (it runs on the grader's own stages 07 and 08,
// never stubs).
const bool kRegistered = register_stage(kStage, [] {
  PathRenderRequest request;
  request.probe_only = 1;
  (void)path_render("scenes/furnace.json", request);
});

// ---- Furnaces ------------------------------------------------------------------------------

// What a path tracer that makes a mistake computes in a furnace of emission 1: the camera's
// hit counts `first_emission`, every vertex k = 0..max_depth + depth_offset (reached with weight r^k) adds its
// direct light d, and vertices after the first add `later_emission` each.
struct Model {
  std::function<double(const Furnace&)> bounce_weight;  // r
  double direct_factor = 1.0;                            // d = direct_factor * a
  double first_emission = 1.0, later_emission = 0.0;
  int depth_offset = 0;  // -1: the vertex at depth == max_depth left out
};
// A common mistake, as what it changes in the correct model (so that two mistakes made together
// are the two changes, in the order of the list).
struct Mistake {
  MessageId hint;
  std::function<void(Model&)> change;
  // Mistakes whose weights explode: the cosine missing weighs a bounce by a / cos(theta), of
  // infinite variance; 1 / pi missing by pi a > 1. Their furnaces with roulette (weights divided
  // by p again and again) are left out, and a mean within 10% of the model (or 4 standard errors)
  // fits.
  bool wild_weights = false;
};
double furnace_value(const Model& model, const Furnace& f) {
  const double r = model.bounce_weight(f), d = model.direct_factor * f.albedo;
  double sum = model.first_emission, reach = 1.0;
  for (int k = 0; k <= f.max_depth + model.depth_offset; ++k) {
    sum += reach * d + (k > 0 ? reach * model.later_emission : 0.0);
    reach *= r;
  }
  return sum;
}
const Model kCorrect{[](const Furnace& f) { return f.albedo; }};
// The bounce weight times `factor(f)`.
std::function<void(Model&)> bounce_weight_times(std::function<double(const Furnace&)> factor) {
  return [factor](Model& m) {
    m.bounce_weight = [inner = m.bounce_weight, factor](const Furnace& f) { return inner(f) * factor(f); };
  };
}
const std::vector<Mistake>& mistakes() {
  static const std::vector<Mistake> models = {
      // The throughput never multiplied: every vertex is reached with weight 1 (roulette divides by
      // the p it survived). First: the other changes of the bounce weight apply to this one.
      {MessageId::path_throughput_not_multiplied, [](Model& m) { m.bounce_weight = [](const Furnace&) { return 1.0; }; }},
      {MessageId::path_roulette_not_divided, bounce_weight_times([](const Furnace& f) { return f.roulette; })},
      {MessageId::path_emission_twice, [](Model& m) { m.later_emission = 1.0; }},
      {MessageId::path_light_black, [](Model& m) { m.first_emission = 0.0; }},
      {MessageId::path_one_surface_short, [](Model& m) { m.depth_offset = -1; }},
      // No direct light at any vertex (a shadow ray that hits the light itself is always blocked):
      // every pixel is the emission the camera sees, exactly 1.
      {MessageId::path_no_direct_light, [](Model& m) { m.direct_factor = 0.0; }},
      {MessageId::path_missing_cosine, bounce_weight_times([](const Furnace&) { return 2.0; }), true},
      // The bounce weighed with f = albedo rather than the BSDF's albedo / pi (the direct light,
      // stage 08's estimator, stays right).
      {MessageId::path_missing_inverse_pi, bounce_weight_times([](const Furnace&) { return kPiD; }), true},
  };
  return models;
}

const FurnaceRender& furnace_render(int index) {
  static std::map<std::pair<int, std::uint64_t>, FurnaceRender> cache;  // by (furnace, seed)
  const std::uint64_t seed = test_seed(100 + static_cast<std::uint64_t>(index));
  const auto found = cache.find({index, seed});
  if (found != cache.end()) return found->second;
  return cache.emplace(std::make_pair(index, seed), render_furnace(index, seed, false)).first->second;
}

bool fits(const Model& model, int index) {
  const FurnaceRender& render = furnace_render(index);
  if (render.not_finite || render.pixel_means.size() < 2) return false;
  return furnace_mean_test(render.pixel_means, furnace_value(model, kFurnaces[index]), kLevel).passed;
}

// Whether the furnaces fit the correct model changed by `made` (one mistake, or two together).
bool fits(const std::vector<const Mistake*>& made) {
  Model model = kCorrect;
  bool wild = false;
  for (const Mistake* mistake : made) {
    mistake->change(model);
    wild = wild || mistake->wild_weights;
  }
  for (int i = 0; i < 3; ++i) {
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

// A furnace is right when its pixels pass both the t-test of their mean and the test of their
// spread (path_support.h: furnace_spread_test).
bool furnace_right(int index) {
  const FurnaceRender& render = furnace_render(index);
  if (render.not_finite || render.pixel_means.size() < 2) return false;
  const double exact = furnace_value(kCorrect, kFurnaces[index]);
  return furnace_exact_test(render.pixel_means, kFurnaces[index], exact, kLevel).passed &&
         furnace_spread_test(render.pixel_means, kFurnaces[index], exact, kLevel).passed;
}

// The hints of a failing test: the fitted models of the furnaces that fit; true when any does.
// A mistake of wild weights is fitted on fewer furnaces and more loosely (Mistake), so it is named
// only when no mistake of finite variance fits: the missing cosine's 2 a is the never-multiplied
// throughput's 1 at albedo 0.5, which only the low-albedo furnace (with roulette) tells apart.
// When no single mistake fits, two made together: named (both) when exactly one pair fits, tame
// pairs before pairs with wild weights (two pairs that fit alike cannot be told apart).
bool hint_mistakes() {
  bool tame_fits = false, any = false;
  for (const bool wild : {false, true})
    for (const Mistake& mistake : mistakes())
      if (mistake.wild_weights == wild && !(wild && tame_fits) && fits({&mistake})) {
        add_hint({mistake.hint, {}});
        tame_fits = tame_fits || !wild;
        any = true;
      }
  if (any) return true;
  const std::vector<Mistake>& all = mistakes();
  for (const bool wild : {false, true}) {
    std::vector<std::pair<const Mistake*, const Mistake*>> fitting;
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
  const double exact = furnace_value(kCorrect, kFurnaces[index]);
  const testkit::MeanTestResult result = furnace_exact_test(render.pixel_means, kFurnaces[index], exact, kLevel);
  const FurnaceSpreadResult spread = furnace_spread_test(render.pixel_means, kFurnaces[index], exact, kLevel);
  if (result.passed && spread.passed) return;
  if (!result.passed) add_furnace_failure(index, result);
  if (!spread.passed) add_furnace_spread_failure(index, spread, exact, kLevel);
  hint_mistakes();
}

GRADED_TEST(kStage, Stage09Path, FurnaceWithoutRoulette, 8) { expect_furnace(0); }
GRADED_TEST(kStage, Stage09Path, FurnaceWithRoulette, 8) { expect_furnace(1); }
GRADED_TEST(kStage, Stage09Path, FurnaceLowAlbedo, 6) { expect_furnace(2); }

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

GRADED_TEST(kStage, Stage09Path, CornellBoxImageMatchesReference, 10) { expect_cornell(0); }
GRADED_TEST(kStage, Stage09Path, SpecularCornellBoxImageMatchesReference, 8) { expect_cornell(1); }

}  // namespace
}  // namespace raylab::grading
