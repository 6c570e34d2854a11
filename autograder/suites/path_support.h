// What stage 09's suite, its reference data and the false-failure measurement
// (autograder/tools/path_false_failures.cpp) share: the renders' settings and the tests' statistics.
// The bonus stage 09b (09b_mis_test.cpp) grades its MIS path tracer with the same furnaces and
// against the same converged Cornell references.
#pragma once

#include "09_path_calls.h"
#include "path_models.h"

#include "raylab/image.h"
#include "raylab/testkit/statistics.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace raylab::grading {

constexpr const char* kCornellScenes[] = {"scenes/cornell.json", "scenes/cornell_specular.json"};
constexpr int kCornellSize = 32;             // pixels, each side
constexpr int kCornellMaxDepth = 8;
constexpr int kReferenceSamples = 4096;      // the converged reference (autograder-regenerate)
constexpr std::uint64_t kReferenceSeed = 9001;
constexpr int kStudentSamples = 128;         // the render graded
constexpr std::uint64_t kStudentSeed = 9;
constexpr int kRegion = 4;                   // pixels per region side
constexpr int kRegionsPerSide = kCornellSize / kRegion;
constexpr int kRegionTestsPerScene = kRegionsPerSide * kRegionsPerSide * 3;  // per region and channel

inline PathRenderRequest cornell_request(int samples_per_pixel, std::uint64_t seed) {
  PathRenderRequest request;
  request.width = request.height = kCornellSize;
  request.samples_per_pixel = samples_per_pixel;
  request.max_depth = kCornellMaxDepth;
  request.roulette_probability = 1.0f;
  request.seed = seed;
  return request;
}

// The furnaces (path_models.h: kFurnaces), each rendered 32x32 at 4 spp: each pixel's mean is one
// value of the t-test. In a sphere, sampling the light by area gives every point the same
// estimate, so the values vary only by the BSDF's samples and the roulette: a distribution with
// light tails, which a t-test judges at its stated rate. (A cube's edges give estimates of
// unbounded variance: over 1,568 seeds the t-statistics of the reference averaged -0.85, and 3%
// fell below -4.)
PathRenderRequest furnace_request(int index, std::uint64_t seed);

// A furnace render: its finite pixel means (the red channel; the furnace is grey) and how many
// pixels were not finite. `mis`: path_radiance_mis (stage 09b) instead of path_radiance.
struct FurnaceRender {
  std::vector<double> pixel_means;
  std::size_t not_finite = 0;
  std::size_t pixel_count() const { return pixel_means.size() + not_finite; }
};
FurnaceRender render_furnace(int index, std::uint64_t seed, bool mis);
// The t-test of a furnace's pixel means against `expected` at `level`, forgiving a deviation of
// kFurnaceTolerance of the expectation. With cosine-weighted bounces and no roulette, a correct
// path tracer gives every pixel nearly the same value, so the test would otherwise judge float
// precision: the reference's furnaces come out 2e-5 low (over 10,000 seeds), from shadow rays to
// light points a few hundredths from the shading point, where the sampled point, rounded off the
// sphere, is found just before the ray's end; a shorter shadow epsilon loses more. Every mistake
// the suite models moves some furnace by 15% or more.
constexpr double kFurnaceTolerance = 1e-3;
testkit::MeanTestResult furnace_mean_test(const std::vector<double>& pixel_means, double expected, double level,
                                          double max_variance = std::numeric_limits<double>::infinity());
// The t-test of a furnace against its exact answer: the pixels' own variance counts only up to
// furnace_variance_bound (a correct path tracer's can be no larger), so noise added to hide a
// bias does not widen it (tests/submissions/hostile_noise_hides_bias.cpp).
testkit::MeanTestResult furnace_exact_test(const std::vector<double>& pixel_means, const Furnace& furnace, double exact,
                                           double level);
// Adds the failure of furnace `index`'s test (`result`, against furnace_exact).
void add_furnace_failure(int index, const testkit::MeanTestResult& result);

// The t-test alone cannot reject a wrong estimator whose weights grow along the path (1 / pi
// missing with roulette: a bounce weight of pi a / p = 3.14 each time a path goes on): its mean is
// huge but so is its spread, and a few pixels of millions make the standard error as large as the
// mean. A correct path tracer's spread is bounded, so a second test of each furnace rejects
// pixels that spread far more than any correct estimator's can.
//   The bound: a correct path's value is at most 1 (the emission the camera sees) + 2 a T_k at each
// vertex k (its direct light a T_k, and with MIS as much again from the BSDF sample), where the
// throughput T_k is a product of independent bounce weights W of mean a and second moment at most
// m = (4/3) a^2 / min(p, a): the uniform hemisphere's weight 2 a cos(theta) (second moment
// 4 a^2 / 3; cosine sampling's is a^2) after a roulette of probability p (the furnace's, or about a
// for a roulette by the throughput). So a pixel mean of `spp` paths has a variance of at most
// E[(1 + 2 a sum_k T_k)^2] / spp, computed exactly from E[T_j T_k] = m^min(j,k) a^|k-j|.
double furnace_variance_bound(const Furnace& furnace);
//   The test: the pixels' mean squared deviation from `expected` (the exact answer) has the
// expectation Var(pixel) <= bound, so by Markov's inequality it exceeds bound / `level` with a
// chance of at most `level`, whatever the distribution of the pixels (heavy tails included). A
// wrong estimator is caught by its mean alone: the mean square is at least (mean - expected)^2.
struct FurnaceSpreadResult {
  bool passed = true;
  double mean_square = 0;  // of the pixels' deviations from `expected`
  double largest = 0;      // the largest pixel
  double limit = 0;        // bound / level: the test fails above it
};
FurnaceSpreadResult furnace_spread_test(const std::vector<double>& pixel_means, const Furnace& furnace, double expected,
                                        double level);
// Adds the failure of furnace `index`'s spread test.
void add_furnace_spread_failure(int index, const FurnaceSpreadResult& result, double expected, double level);
// No points without work: a correct path tracer's values cannot all lie near the furnace's answer.
// Russian roulette (the contract: go on with probability p = context.continue_probability(depth,
// throughput), from the camera ray's hit on) ends a share 1 - p of the paths at the first surface,
// each with the emission 1 and that surface's direct light D, which is never negative and is a on
// average (with MIS, its two weighted samples together). So a path's value is at most
// h = 1 + t a with a chance of at least q = (1 - p)(1 - 1 / t) (Markov's inequality on D),
// whatever the path tracer samples. h lies halfway between 1 + a + a^2 (a path that ends at the
// second surface after a cosine-weighted bounce, where a roulette by the throughput, which never
// stops a path at the first, ends most: path_throughput_roulette) and the exact answer.
//   The test renders the furnace at 1 sample per pixel, one path per pixel, and counts the paths
// whose value is at most h. That count is at least Binomial(paths, q), so the test fails a correct
// path tracer with a chance of at most `level` (an exact binomial tail, no approximation). A
// constant (the answer returned without tracing anything) and a path tracer that never plays the
// roulette have no such paths. Only the furnaces with roulette (p < 1) are tested: without it, a
// correct path tracer with cosine-weighted bounces is nearly noiseless in a sphere.
constexpr int kShortPathsSide = 64;  // pixels, each side: 4,096 paths
FurnaceRender render_furnace_paths(int index, std::uint64_t seed, bool mis);

// A small picture of the Cornell box (8 x 8 pixels, 1 path each) rendered twice with the same
// seed: how many pixels differ, bit for bit. A path tracer that takes every random number from
// its sampler renders the same picture twice; one that calls rand() does not (in the box, unlike
// in a furnace, every random direction changes a path's value).
struct RepeatResult {
  std::size_t differing = 0, pixels = 0;
};
RepeatResult repeat_test(std::uint64_t seed);
void add_repeat_failure(const RepeatResult& result);
double short_path_limit(const Furnace& furnace);        // h
double short_path_least_share(const Furnace& furnace);  // q
struct ShortPathsResult {
  bool passed = true;
  long long short_paths = 0, paths = 0;
  double limit = 0, least_share = 0;
  double p_value = 1;  // P(Binomial(paths, least_share) <= short_paths)
};
// `paths.not_finite` count as paths that are not short.
ShortPathsResult furnace_short_paths_test(const FurnaceRender& paths, const Furnace& furnace, double level);
// Adds the failure of furnace `index`'s test of short paths and its hint.
void add_furnace_short_paths_failure(int index, const ShortPathsResult& result, double level);

// Adds the failure and the hint for `count` of `total` pixels not finite.
void add_not_finite(std::size_t count, std::size_t total);

// The stage's statistical tests: 3 furnace t-tests, their 3 spread tests, the 2 tests of short
// paths (the furnaces with roulette) and the region z-tests of both boxes.
constexpr int kPathStatisticalTests = 3 + 3 + 2 + 2 * kRegionTestsPerScene;
double path_test_level();  // each test's level: the stage's 1 in 1,000, Sidak-corrected
// Stage 09b's: 2 furnace t-tests (kFurnaces[0] and [1]), their 2 spread tests, the test of short
// paths of kFurnaces[1] and the region z-tests of both boxes.
constexpr int kMisStatisticalTests = 2 + 2 + 1 + 2 * kRegionTestsPerScene;
double mis_test_level();

// The region z-tests of a Cornell render: per 4x4 region and channel, z = (yours - reference) /
// sqrt(variance), the variance the larger of yours and the reference's (scaled to your sample
// count) plus the reference mean's own.
// How much noisier than the reference estimator's a student's picture may count in the region
// z-tests: its variance of the mean, over the whole picture, up to this multiple of the reference's
// (scaled to the student's samples) widens the tests as the noise it adds; past it, no more. A
// path tracer that follows the contract (its sampling choices included: uniform or cosine bounces,
// MIS, another roulette) stays well under it (docs/instructors.md); a biased estimate with noise
// added to hide the bias does not (tests/submissions/hostile_noise_hides_bias.cpp).
constexpr double kNoisierThanReferenceAllowed = 4.0;

struct RegionTest {
  int failures = 0;
  double z_limit = 0;
  // The student's variance of the mean over the whole picture, as a multiple of the reference's
  // scaled to the student's samples (what the stage server reported: it never widens a test past
  // kNoisierThanReferenceAllowed).
  double variance_ratio = 0;
  double worst_z = 0, worst_mean = 0, worst_expected = 0;
  int worst_x = 0, worst_y = 0, worst_channel = 0;
  std::vector<double> z_scores;  // region by region (row-major), channel by channel
};
// `level`: each z-test's significance level (path_test_level() for stage 09, mis_test_level() for 09b).
RegionTest region_z_test(const PathRenderResult& yours, int your_samples, const Image& reference_mean,
                         const Image& reference_variance_of_mean, int reference_samples,
                         double level = path_test_level());


// The image test of a path tracer: renders kCornellScenes[scene_index] kCornellSize square at
// kStudentSamples spp with the student's path_radiance (or path_radiance_mis when `mis`) and seed
// `seed`, z-tests it region by region against stage 09's converged reference
// (autograder/reference/09_path_cases.json) at `level`, writes <stage_id>-<scene>.png (yours |
// reference | z-scores), and adds the note and, when regions fail, the failure. The HTML report
// shows the three parts (each also written on its own) always, or with `report_only_failures`
// only when regions fail (stage 09b: the report tests check every picture of the page on one
// screenshot, at most 16384 pixels tall, which a failing camera's page nearly fills). nullopt
// when pixels are not finite (the failure and the hint are added).
std::optional<RegionTest> expect_cornell_matches_reference(const std::string& stage_id, int scene_index, bool mis,
                                                           std::uint64_t seed, double level,
                                                           bool report_only_failures = false);

}  // namespace raylab::grading
