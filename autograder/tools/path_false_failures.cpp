// Measures how often stage 09's statistical tests fail the reference solution by bad luck: the
// furnace t-tests and the Cornell region z-tests of autograder/suites/09_path_test.cpp, with
// the same settings and the same reference data, rendered with N seeds other than the graded
// one. The design rate is 1 in 1,000 for the whole stage; also prints how many single region
// tests pass |z| = 3 and 4, against the normal distribution's share, to show the tails.
//   autograder-path-false-failures --seeds 200
#include "path_support.h"
#include "support.h"

#include "raylab/testkit/statistics.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
  using namespace raylab;
  using namespace raylab::grading;
  CLI::App app{"Measure stage 09's false failures on the reference solution"};
  int seeds = 100;
  app.add_option("--seeds", seeds, "How many independent gradings")->check(CLI::Range(1, 100000));
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
  for (int seed = 1; seed <= seeds; ++seed) {
    bool failed = false;
    for (int f = 0; f < 3; ++f) {
      const PathRenderResult render = path_render("scenes/furnace.json", furnace_request(f, 1000003ull * seed + f));
      std::vector<double> values;
      for (const glm::vec3& v : render.mean.pixels()) values.push_back(v.x);
      if (!testkit::mean_test(values, furnace_exact(kFurnaces[f]), level).passed) {
        ++furnace_failures;
        failed = true;
      }
    }
    for (int s = 0; s < 2; ++s) {
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
  std::printf("09_path false failures of the reference over %d seeds: %lld gradings failed (design: at most %.4g "
              "per grading, %.3g expected)\n",
              seeds, stage_failures, testkit::kGraderFalseFailureRate, testkit::kGraderFalseFailureRate * seeds);
  std::printf("  furnace t-tests failed: %lld of %d; region z-tests failed: %lld of %lld (level %.3g each)\n",
              furnace_failures, 3 * seeds, region_failures, region_tests, level);
  std::printf("  region |z| > 3: %lld of %lld (normal: %.1f); |z| > 4: %lld (normal: %.2f)\n", beyond_3, region_tests,
              normal_3 * static_cast<double>(region_tests), beyond_4, normal_4 * static_cast<double>(region_tests));
  return 0;
}
