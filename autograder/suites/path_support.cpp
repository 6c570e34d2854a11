#include "path_support.h"

#include "grading.h"
#include "support.h"

#include "raylab/math.h"
#include "raylab/testkit/statistics.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace raylab::grading {

PathRenderRequest furnace_request(int index, std::uint64_t seed) {
  const Furnace& f = kFurnaces[index];
  PathRenderRequest request;
  request.width = request.height = 32;
  request.samples_per_pixel = 4;
  request.max_depth = f.max_depth;
  request.roulette_probability = static_cast<float>(f.roulette);
  request.albedo = static_cast<float>(f.albedo);
  request.seed = seed;
  return request;
}

namespace {

// The furnace rendered as `request` asks: its finite pixel means (red) and the count of the others.
FurnaceRender furnace_pixels(PathRenderRequest request, bool mis) {
  request.mis = mis ? 1 : 0;
  const PathRenderResult result = path_render("scenes/furnace.json", request);
  FurnaceRender render;
  for (const glm::vec3& v : result.mean.pixels()) {
    if (!is_finite(v)) ++render.not_finite;
    else render.pixel_means.push_back(v.x);
  }
  return render;
}

}  // namespace

FurnaceRender render_furnace(int index, std::uint64_t seed, bool mis) {
  return furnace_pixels(furnace_request(index, seed), mis);
}

testkit::MeanTestResult furnace_mean_test(const std::vector<double>& pixel_means, double expected, double level,
                                          double max_variance) {
  return testkit::mean_test(pixel_means, expected, level, kFurnaceTolerance * std::fabs(expected), max_variance);
}

testkit::MeanTestResult furnace_exact_test(const std::vector<double>& pixel_means, const Furnace& furnace, double exact,
                                           double level) {
  return furnace_mean_test(pixel_means, exact, level, furnace_variance_bound(furnace));
}

void add_furnace_failure(int index, const testkit::MeanTestResult& result) {
  const Furnace& f = kFurnaces[index];
  add_failure({MessageId::path_failure_furnace,
               {{"albedo", gtest_text(f.albedo)},
                {"roulette", gtest_text(f.roulette)},
                {"depth", std::to_string(f.max_depth)},
                {"count", std::to_string(result.count)},
                {"mean", gtest_text(result.mean)},
                {"error", gtest_text(result.standard_error)},
                {"expected", gtest_text(result.expected_mean)},
                {"p_value", gtest_text(result.p_value)},
                {"level", gtest_text(result.significance_level)}}});
}

double furnace_variance_bound(const Furnace& furnace) {
  const double a = furnace.albedo;
  const double m = (4.0 / 3.0) * a * a / std::min(furnace.roulette, a);
  // E[(1 + 2 a S)^2] with S = sum_k T_k: 1 + 4 a E[S] + 4 a^2 E[S^2].
  double sum = 0, sum_squared = 0;
  for (int j = 0; j <= furnace.max_depth; ++j) {
    sum += std::pow(a, j);
    for (int k = 0; k <= furnace.max_depth; ++k)
      sum_squared += std::pow(m, std::min(j, k)) * std::pow(a, std::abs(k - j));
  }
  const PathRenderRequest request = furnace_request(0, 0);
  return (1.0 + 4.0 * a * sum + 4.0 * a * a * sum_squared) / request.samples_per_pixel;
}

FurnaceSpreadResult furnace_spread_test(const std::vector<double>& pixel_means, const Furnace& furnace, double expected,
                                        double level) {
  FurnaceSpreadResult result;
  result.limit = furnace_variance_bound(furnace) / level;
  if (pixel_means.empty()) return result;
  for (const double v : pixel_means) {
    result.mean_square += (v - expected) * (v - expected);
    result.largest = std::max(result.largest, v);
  }
  result.mean_square /= static_cast<double>(pixel_means.size());
  result.passed = result.mean_square <= result.limit;
  return result;
}

void add_furnace_spread_failure(int index, const FurnaceSpreadResult& result, double expected, double level) {
  const Furnace& f = kFurnaces[index];
  add_failure({MessageId::path_failure_furnace_spread,
               {{"albedo", gtest_text(f.albedo)},
                {"roulette", gtest_text(f.roulette)},
                {"depth", std::to_string(f.max_depth)},
                {"expected", gtest_text(expected)},
                {"spread", gtest_text(result.mean_square)},
                {"largest", gtest_text(result.largest)},
                {"bound", gtest_text(furnace_variance_bound(f))},
                {"limit", gtest_text(result.limit)},
                {"level", gtest_text(level)}}});
}

FurnaceRender render_furnace_paths(int index, std::uint64_t seed, bool mis) {
  PathRenderRequest request = furnace_request(index, seed);
  request.width = request.height = kShortPathsSide;
  request.samples_per_pixel = 1;  // one path per pixel
  return furnace_pixels(request, mis);
}

RepeatResult repeat_test(std::uint64_t seed) {
  PathRenderRequest request;
  request.width = request.height = 8;
  request.samples_per_pixel = 1;
  request.seed = seed;
  const PathRenderResult first = path_render("scenes/cornell.json", request);
  const PathRenderResult second = path_render("scenes/cornell.json", request);
  return {bitwise_differences(first.mean.pixels(), second.mean.pixels()), first.mean.pixels().size()};
}

void add_repeat_failure(const RepeatResult& result) {
  add_failure({MessageId::path_failure_not_repeatable,
               {{"count", std::to_string(result.differing)}, {"total", std::to_string(result.pixels)}}});
}

double short_path_limit(const Furnace& furnace) {
  const double a = furnace.albedo;
  return 0.5 * (1.0 + a + a * a + furnace_exact(furnace));
}

double short_path_least_share(const Furnace& furnace) {
  const double t = (short_path_limit(furnace) - 1.0) / furnace.albedo;
  return (1.0 - furnace.roulette) * (1.0 - 1.0 / t);
}

ShortPathsResult furnace_short_paths_test(const FurnaceRender& paths, const Furnace& furnace, double level) {
  ShortPathsResult result;
  result.limit = short_path_limit(furnace);
  result.least_share = short_path_least_share(furnace);
  result.paths = static_cast<long long>(paths.pixel_count());
  for (const double v : paths.pixel_means) result.short_paths += v <= result.limit;
  if (result.paths == 0) return result;
  // P(K <= k) for K ~ Binomial(n, q) is P(n - K >= n - k), n - K ~ Binomial(n, 1 - q).
  result.p_value = testkit::binomial_upper_tail(result.paths - result.short_paths, result.paths, 1.0 - result.least_share);
  result.passed = result.p_value >= level;
  return result;
}

void add_furnace_short_paths_failure(int index, const ShortPathsResult& result, double level) {
  const Furnace& f = kFurnaces[index];
  add_failure({MessageId::path_failure_furnace_short_paths,
               {{"albedo", gtest_text(f.albedo)},
                {"roulette", gtest_text(f.roulette)},
                {"depth", std::to_string(f.max_depth)},
                {"count", std::to_string(result.short_paths)},
                {"total", std::to_string(result.paths)},
                {"limit", gtest_text(result.limit)},
                {"share", gtest_text(result.least_share)},
                {"least", std::to_string(std::llround(result.least_share * static_cast<double>(result.paths)))},
                {"p_value", gtest_text(result.p_value)},
                {"level", gtest_text(level)}}});
  add_hint({MessageId::path_roulette_not_played, {{"roulette", gtest_text(f.roulette)}}});
}

void add_not_finite(std::size_t count, std::size_t total) {
  add_failure({MessageId::path_failure_not_finite, {{"count", std::to_string(count)}, {"total", std::to_string(total)}}});
  add_hint({MessageId::path_not_finite, {{"count", std::to_string(count)}, {"total", std::to_string(total)}}});
}

double path_test_level() {
  static const double level = testkit::sidak_level(testkit::kGraderFalseFailureRate, kPathStatisticalTests);
  return level;
}

double mis_test_level() {
  static const double level = testkit::sidak_level(testkit::kGraderFalseFailureRate, kMisStatisticalTests);
  return level;
}

RegionTest region_z_test(const PathRenderResult& yours, int your_samples, const Image& reference_mean,
                         const Image& reference_variance_of_mean, int reference_samples, double level) {
  RegionTest result;
  result.z_limit = testkit::normal_quantile(1.0 - level / 2.0);
  const double n = kRegion * kRegion;
  // The spread the stage server reports counts up to kNoisierThanReferenceAllowed times the
  // reference estimator's, over the whole picture: more noise cannot hide a bias.
  double total_yours = 0, total_reference_scaled = 0;
  for (int y = 0; y < kCornellSize; ++y)
    for (int x = 0; x < kCornellSize; ++x)
      for (int c = 0; c < 3; ++c) {
        total_yours += yours.variance_of_mean.at(x, y)[c];
        total_reference_scaled += static_cast<double>(reference_variance_of_mean.at(x, y)[c]) * reference_samples / your_samples;
      }
  result.variance_ratio = total_reference_scaled > 0 ? total_yours / total_reference_scaled : 0.0;
  const double counted = result.variance_ratio > kNoisierThanReferenceAllowed
                             ? kNoisierThanReferenceAllowed / result.variance_ratio
                             : 1.0;  // the share of the student's variance that counts
  for (int ry = 0; ry < kRegionsPerSide; ++ry)
    for (int rx = 0; rx < kRegionsPerSide; ++rx)
      for (int c = 0; c < 3; ++c) {
        double mean = 0, expected = 0, variance_yours = 0, variance_reference_scaled = 0, variance_reference = 0;
        for (int y = ry * kRegion; y < (ry + 1) * kRegion; ++y)
          for (int x = rx * kRegion; x < (rx + 1) * kRegion; ++x) {
            mean += yours.mean.at(x, y)[c];
            variance_yours += yours.variance_of_mean.at(x, y)[c];
            expected += reference_mean.at(x, y)[c];
            const double reference_variance = reference_variance_of_mean.at(x, y)[c];
            variance_reference += reference_variance;
            variance_reference_scaled += reference_variance * reference_samples / your_samples;
          }
        mean /= n;
        expected /= n;
        const double variance =
            (std::max(counted * variance_yours, variance_reference_scaled) + variance_reference) / (n * n);
        const double z = variance > 0 ? (mean - expected) / std::sqrt(variance) : (mean == expected ? 0.0 : 1e9);
        result.z_scores.push_back(z);
        if (!(std::fabs(z) <= result.z_limit)) {
          ++result.failures;
          if (!(std::fabs(z) <= std::fabs(result.worst_z))) {
            result.worst_z = z;
            result.worst_x = rx * kRegion;
            result.worst_y = ry * kRegion;
            result.worst_channel = c;
            result.worst_mean = mean;
            result.worst_expected = expected;
          }
        }
      }
  return result;
}

namespace {

glm::vec3 z_colour(double z, double limit) {
  // Pale grey within the noise, shading to full blue (below the reference) or red (above) at the
  // test's limit; NaN is magenta.
  if (std::isnan(z)) return glm::vec3(1.0f, 0.0f, 1.0f);
  const float t = static_cast<float>(std::min(1.0, std::fabs(z) / limit));
  const glm::vec3 grey(0.8f), full = z < 0 ? glm::vec3(0.0f, 0.1f, 1.0f) : glm::vec3(1.0f, 0.05f, 0.0f);
  return grey * (1.0f - t) + full * t;
}

// The command that prints path_trace_pixel's trace on the student's machine (with the student's
// own geometry, which the picture replaced by the grader's).
std::string path_trace_command(const std::string& scene, const PathRenderRequest& request, const PixelTrace& trace,
                               bool chinese) {
  return std::string("build/bin/raylab trace ") + (chinese ? "--lang zh " : "") + "--integrator " +
         (request.mis ? "mis" : "path") + " --width " + std::to_string(request.width) + " --height " +
         std::to_string(request.height) + " --spp " + std::to_string(request.samples_per_pixel) + " --sample " +
         std::to_string(trace.settings.sample) + " --seed " + std::to_string(request.seed) + " --max-depth " +
         std::to_string(request.max_depth) + " --roulette " + gtest_text(request.roulette_probability) + " --pixel " +
         std::to_string(trace.x) + " " + std::to_string(trace.y) + " " + scene;
}

// A failing Cornell picture: the pixel of the worst region whose mean differs most from the
// reference's in the worst channel, traced sample by sample in the stage server
// (path_trace_pixel), under the pictures and as a note; nothing when the trace cannot be had.
void attach_worst_region_trace(ImageComparison& images, const std::string& scene, const PathRenderRequest& request,
                               const PathRenderResult& render, const Image& reference_mean, const RegionTest& test) {
  int x = test.worst_x, y = test.worst_y;
  double largest = -1;
  for (int py = test.worst_y; py < test.worst_y + kRegion; ++py)
    for (int px = test.worst_x; px < test.worst_x + kRegion; ++px) {
      const double difference =
          std::fabs(double(render.mean.at(px, py)[test.worst_channel]) - reference_mean.at(px, py)[test.worst_channel]);
      if (difference > largest) {
        largest = difference;
        x = px;
        y = py;
      }
    }
  const bool chinese = language() == Language::Chinese;
  PixelTrace trace;
  try {
    trace = path_trace_pixel(scene, request, x, y, chinese);
  } catch (const std::exception&) {
    return;
  }
  const std::string command = path_trace_command(scene, request, trace, chinese);
  attach_pixel_trace(images, std::move(trace), command);
}

}  // namespace

std::optional<RegionTest> expect_cornell_matches_reference(const std::string& stage_id, int scene_index, bool mis,
                                                           std::uint64_t seed, double level, bool report_only_failures) {
  const std::string scene = kCornellScenes[scene_index];
  const nlohmann::json cases = load_reference_cases("09_path");
  const nlohmann::json& reference = cases.at(scene);
  const int reference_spp = reference.at("samples_per_pixel").get<int>();
  PathRenderRequest request = cornell_request(kStudentSamples, seed);
  request.mis = mis ? 1 : 0;
  const PathRenderResult render = path_render(scene, request);
  std::size_t not_finite = 0;
  for (const glm::vec3& v : render.mean.pixels())
    if (!is_finite(v)) ++not_finite;
  if (not_finite) {
    add_not_finite(not_finite, render.mean.pixels().size());
    return std::nullopt;
  }
  Image reference_mean(kCornellSize, kCornellSize), reference_variance(kCornellSize, kCornellSize);
  for (int y = 0; y < kCornellSize; ++y)
    for (int x = 0; x < kCornellSize; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kCornellSize + static_cast<std::size_t>(x);
      reference_mean.at(x, y) = vec3_from_json(reference.at("mean").at(i));
      reference_variance.at(x, y) = vec3_from_json(reference.at("variance_of_mean").at(i));
    }
  const RegionTest test =
      region_z_test(render, kStudentSamples, reference_mean, reference_variance, reference_spp, level);
  Image z_picture(kRegionsPerSide, kRegionsPerSide);
  for (int ry = 0; ry < kRegionsPerSide; ++ry)
    for (int rx = 0; rx < kRegionsPerSide; ++rx) {
      double z_shown = 0;
      for (int c = 0; c < 3; ++c) {
        const double z = test.z_scores[static_cast<std::size_t>((ry * kRegionsPerSide + rx) * 3 + c)];
        if (!(std::fabs(z) <= std::fabs(z_shown))) z_shown = z;
      }
      z_picture.at(rx, ry) = z_colour(z_shown, test.z_limit);
    }
  // yours | reference | z-scores, each kCornellSize pixels scaled 4x.
  const int scale = 4, side = kCornellSize * scale;
  Image picture(3 * side, side);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      picture.at(x, y) = render.mean.at(x / scale, y / scale);
      picture.at(x + side, y) = reference_mean.at(x / scale, y / scale);
      picture.at(x + 2 * side, y) = z_picture.at(x / scale / kRegion, y / scale / kRegion);
    }
  const std::string directory = output_directory();
  std::filesystem::create_directories(directory);
  const std::string name = stage_id + "-" + std::filesystem::path(scene).stem().string();
  const std::string path = directory + "/" + name + ".png";
  write_image(picture, path);
  // Each of the three on its own, for the HTML report (yours | reference | z-scores, and the slider).
  if (!report_only_failures || test.failures > 0) {
    auto part = [&](int index) {
      Image image(side, side);
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) image.at(x, y) = picture.at(x + index * side, y);
      return image;
    };
    write_image(part(0), directory + "/" + name + "-yours.png");
    write_image(part(1), directory + "/" + name + "-reference.png");
    write_image(part(2), directory + "/" + name + "-z.png");
    ImageComparison images{name + "-yours.png", name + "-reference.png", name + "-z.png"};
    images.difference_label = Message{MessageId::report_z_scores};
    if (test.failures > 0) attach_worst_region_trace(images, scene, request, render, reference_mean, test);
    add_image(images);
  }
  add_note({MessageId::path_note_picture, {{"scene", scene}, {"path", path}}});
  add_note({MessageId::path_note_noise, {{"scene", scene}, {"ratio", gtest_text(test.variance_ratio)}}});
  if (test.failures == 0) return test;
  if (test.variance_ratio > kNoisierThanReferenceAllowed)
    add_hint({MessageId::path_too_noisy,
              {{"ratio", gtest_text(test.variance_ratio)}, {"limit", gtest_text(kNoisierThanReferenceAllowed)}}});
  add_failure({MessageId::path_failure_regions,
               {{"scene", scene},
                {"failures", std::to_string(test.failures)},
                {"tests", std::to_string(kRegionTestsPerScene)},
                {"limit", gtest_text(test.z_limit)},
                {"x", std::to_string(test.worst_x)},
                {"y", std::to_string(test.worst_y)},
                {"channel", std::to_string(test.worst_channel)},
                {"mean", gtest_text(test.worst_mean)},
                {"expected", gtest_text(test.worst_expected)},
                {"z", gtest_text(test.worst_z)}}});
  return test;
}

}  // namespace raylab::grading
