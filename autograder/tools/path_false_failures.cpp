// Measures how often stage 09's statistical tests fail the reference solution by bad luck: the
// furnace t-tests, their spread tests, the tests of short paths and the Cornell region z-tests of
// autograder/suites/09_path_test.cpp, with the same settings and the same reference data,
// rendered with N seeds other than the graded one. The design rate is 1 in 1,000 for the whole stage; also prints how many single region
// tests pass |z| = 3 and 4, and how many furnace t-statistics pass |t| = 3 and 4, against the
// normal distribution's share, to show the tails.
//   autograder-path-false-failures --seeds 200
//   autograder-path-false-failures --seeds 10000 --furnaces-only
#include "path_support.h"
#include "support.h"

#include "raylab/testkit/statistics.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
  using namespace raylab;
  using namespace raylab::grading;
  CLI::App app{"Measure stage 09's false failures on the reference solution"};
  int seeds = 100;
  app.add_option("--seeds", seeds, "How many independent gradings")->check(CLI::Range(1, 100000));
  bool furnaces_only = false;
  app.add_flag("--furnaces-only", furnaces_only, "Only the furnaces (milliseconds a seed: for their tails)");
  CLI11_PARSE(app, argc, argv);

  const nlohmann::json cases = load_reference_cases("09_path");
  Image reference_mean[2], reference_variance[2];
  int reference_samples[2] = {0, 0};
  for (int s = 0; s < 2; ++s) {
    const nlohmann::json& data = cases.at(kCornellScenes[s]);
    reference_samples[s] = data.at("samples_per_pixel").get<int>();
    reference_mean[s] = Image(kCornellSize, kCornellSize);
    reference_variance[s] = Image(kCornellSize, kCornellSize);
    for (int y = 0; y < kCornellSize; ++y)
      for (int x = 0; x < kCornellSize; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * kCornellSize + static_cast<std::size_t>(x);
        reference_mean[s].at(x, y) = vec3_from_json(data.at("mean").at(i));
        reference_variance[s].at(x, y) = vec3_from_json(data.at("variance_of_mean").at(i));
      }
  }
  const double level = path_test_level();
  long long stage_failures = 0, furnace_failures = 0, region_failures = 0, beyond_3 = 0, beyond_4 = 0, region_tests = 0;
  // Each furnace's t-statistics before the tolerance, (mean - exact) / standard error: their mean
  // and tails show whether the t-test's normal approximation holds (a furnace without roulette has
  // almost no noise, so there they show float rounding instead).
  testkit::RunningMoments furnace_t[3], furnace_deviation[3];
  long long furnace_beyond_3[3] = {0, 0, 0}, furnace_beyond_4[3] = {0, 0, 0};
  // The spread tests: each furnace's largest mean squared deviation as a share of its limit.
  double furnace_spread_share[3] = {0, 0, 0};
  // The tests of short paths (the furnaces with roulette): the fewest short paths, as a share of
  // the paths, against the least share the test assumes, and the smallest p-value.
  double fewest_short_share[3] = {1, 1, 1}, smallest_short_p[3] = {1, 1, 1};
  for (int seed = 1; seed <= seeds; ++seed) {
    bool failed = false;
    for (int f = 0; f < 3; ++f) {
      const FurnaceRender render = render_furnace(f, 1000003ull * seed + f, false);
      const double exact = furnace_exact(kFurnaces[f]);
      const testkit::MeanTestResult test = furnace_exact_test(render.pixel_means, kFurnaces[f], exact, level);
      const FurnaceSpreadResult spread = furnace_spread_test(render.pixel_means, kFurnaces[f], exact, level);
      furnace_spread_share[f] = std::max(furnace_spread_share[f], spread.mean_square / spread.limit);
      if (render.not_finite || !test.passed || !spread.passed) {
        ++furnace_failures;
        failed = true;
      }
      if (kFurnaces[f].roulette < 1.0) {
        const ShortPathsResult short_paths =
            furnace_short_paths_test(render_furnace_paths(f, 3000017ull * seed + f, false), kFurnaces[f], level);
        fewest_short_share[f] = std::min(fewest_short_share[f], static_cast<double>(short_paths.short_paths) /
                                                                     static_cast<double>(short_paths.paths));
        smallest_short_p[f] = std::min(smallest_short_p[f], short_paths.p_value);
        if (!short_paths.passed && !(render.not_finite || !test.passed || !spread.passed)) {
          ++furnace_failures;
          failed = true;
        }
      }
      furnace_deviation[f].add((test.mean - exact) / exact);
      if (test.standard_error > 0) {
        const double t = (test.mean - exact) / test.standard_error;
        furnace_t[f].add(t);
        furnace_beyond_3[f] += std::fabs(t) > 3.0;
        furnace_beyond_4[f] += std::fabs(t) > 4.0;
      }
    }
    for (int s = 0; s < (furnaces_only ? 0 : 2); ++s) {
      const PathRenderResult render =
          path_render(kCornellScenes[s], cornell_request(kStudentSamples, 2000003ull * seed + s));
      const RegionTest test =
          region_z_test(render, kStudentSamples, reference_mean[s], reference_variance[s], reference_samples[s]);
      region_failures += test.failures;
      if (test.failures) failed = true;
      for (double z : test.z_scores) {
        ++region_tests;
        beyond_3 += std::fabs(z) > 3.0;
        beyond_4 += std::fabs(z) > 4.0;
      }
    }
    stage_failures += failed;
    std::fprintf(stderr, "\rseed %d/%d: %lld stage failures so far", seed, seeds, stage_failures);
  }
  std::fprintf(stderr, "\n");
  const double normal_3 = 2.0 * (1.0 - testkit::normal_cdf(3.0)), normal_4 = 2.0 * (1.0 - testkit::normal_cdf(4.0));
  if (furnaces_only) {
    std::printf("09_path furnaces of the reference over %d seeds: %lld of %d failed their t-test, spread test or test of short paths (level %.3g each)\n", seeds,
                furnace_failures, 3 * seeds, level);
  } else {
    std::printf("09_path false failures of the reference over %d seeds: %lld gradings failed (design: at most %.4g "
                "per grading, %.3g expected)\n",
                seeds, stage_failures, testkit::kGraderFalseFailureRate, testkit::kGraderFalseFailureRate * seeds);
    std::printf("  furnace t-tests, spread tests or tests of short paths failed: %lld of %d; region z-tests failed: %lld of %lld (level %.3g each)\n",
                furnace_failures, 3 * seeds, region_failures, region_tests, level);
    std::printf("  region |z| > 3: %lld of %lld (normal: %.1f); |z| > 4: %lld (normal: %.2f)\n", beyond_3, region_tests,
                normal_3 * static_cast<double>(region_tests), beyond_4, normal_4 * static_cast<double>(region_tests));
  }
  for (int f = 0; f < 3; ++f) {
    const double count = static_cast<double>(furnace_t[f].count());
    std::printf("  furnace %d (albedo %g, roulette %g, depth %d): mean %.2e off the exact value (relative); t mean "
                "%.3f, sd %.3f; |t| > 3: %lld of %zu (normal: %.1f); |t| > 4: %lld (normal: %.2f)\n",
                f, kFurnaces[f].albedo, kFurnaces[f].roulette, kFurnaces[f].max_depth, furnace_deviation[f].mean(),
                furnace_t[f].mean(), std::sqrt(furnace_t[f].variance()), furnace_beyond_3[f], furnace_t[f].count(),
                normal_3 * count, furnace_beyond_4[f], normal_4 * count);
    std::printf("    spread test: the largest mean squared deviation was %.3g of its limit\n", furnace_spread_share[f]);
    if (kFurnaces[f].roulette < 1.0)
      std::printf("    short paths (at most %.4g): the fewest were %.3g of the paths (the test assumes at least %.3g); "
                  "smallest p-value %.3g\n",
                  short_path_limit(kFurnaces[f]), fewest_short_share[f], short_path_least_share(kFurnaces[f]),
                  smallest_short_p[f]);
  }
  return 0;
}
