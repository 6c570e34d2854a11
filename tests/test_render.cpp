// The renderer end to end, with the reference stages: determinism across thread counts, the
// background, hard shadows without light leaks, and no shadow acne at grazing light.
// Scenes are written as JSON in the test and read through parse_scene, like any scene file.
#include "raylab/geometry.h"
#include "raylab/integrator.h"
#include "raylab/random.h"
#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/stages/01_camera_rays.h"
#include "raylab/testkit/random_values.h"
#include "raylab/testkit/statistics.h"

#include "test_helpers.h"

#include "../solutions/05c_wide_bvh/fast_tree.h"  // the reference's own trees

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace raylab {
namespace {

using testing::source_path;

Image render_with_threads(const Scene& scene, int threads) {
  RenderSettings settings;
  settings.max_depth = scene.max_depth;
  settings.threads = threads;
  return render(scene, settings);
}

float brightest_channel(const glm::vec3& c) { return std::max({c.x, c.y, c.z}); }

TEST(Render, OneAndTwoThreadsGiveIdenticalPixels) {
  // render.h promises bit-identical images for any thread count: the autograder compares
  // students' images with references rendered on other machines.
  Scene scene = load_scene(source_path("scenes/whitted.json"));
  scene.camera.width = 32;
  scene.camera.height = 24;
  const Image one = render_with_threads(scene, 1);
  const Image two = render_with_threads(scene, 2);
  ASSERT_EQ(one.width(), 32);
  ASSERT_EQ(one.height(), 24);
  ASSERT_EQ(two.width(), 32);
  ASSERT_EQ(two.height(), 24);
  int differing = 0;
  for (int y = 0; y < one.height(); ++y)
    for (int x = 0; x < one.width(); ++x)
      if (std::memcmp(&one.at(x, y), &two.at(x, y), sizeof(glm::vec3)) != 0 && ++differing <= 5)
        ADD_FAILURE() << "pixel (" << x << ", " << y << "): 1 thread " << one.at(x, y)
                      << ", 2 threads " << two.at(x, y);
  EXPECT_EQ(differing, 0) << "pixels that differ between --threads 1 and --threads 2";

  // The picture must show something besides the background, or the comparison proves little.
  int not_background = 0;
  for (const glm::vec3& pixel : one.pixels()) not_background += pixel != scene.background;
  EXPECT_GT(not_background, 32 * 24 / 20)
      << "pixels other than the background, out of " << 32 * 24 << " (the spheres and floor "
         "cover about a tenth of the picture)";
}

// The scene's geometry with and without the reference's own tree (TracingFunctions::own_tree:
// one SAH tree over every triangle, tested inlined, against a median tree per mesh and a call
// per triangle) must
// find the same closest t for every ray, bit for bit, and the same occlusion: camera rays at
// 64 x 48, and rays from points spread over the scene's box in every direction. The triangle
// found may differ only on a tie (two triangles at the same t: a shared edge, a box's face on
// the floor), and then the same t is what this checks. own_tree: the reference's 8-wide tree
// (as raylab-reference traces, where the CPU runs it) or 4-wide one.
void expect_same_hits_with_own_tree(const std::string& scene_file, TriangleTreeBuilder own_tree) {
  Scene scene = load_scene(source_path(scene_file));
  scene.camera.width = 64;
  scene.camera.height = 48;
  TracingFunctions with_own_tree;
  with_own_tree.own_tree = own_tree;
  const SceneGeometry by_calls(scene, Acceleration::Bvh, TriangleTest::MollerTrumbore);
  const SceneGeometry inlined(scene, Acceleration::Bvh, TriangleTest::MollerTrumbore, with_own_tree);
  SCOPED_TRACE(inlined.tree_choice().own_tree);
  ASSERT_FALSE(inlined.tree_choice().own_tree.empty()) << scene_file << ": one tree over every triangle";
  Bounds3 scene_box;
  for (const TriangleMesh& mesh : scene.meshes)
    for (const glm::vec3& position : mesh.positions) scene_box.extend(position);
  for (const Sphere& sphere : scene.spheres) {
    scene_box.extend(sphere.center - glm::vec3(sphere.radius));
    scene_box.extend(sphere.center + glm::vec3(sphere.radius));
  }
  std::vector<Ray> rays;
  for (int y = 0; y < scene.camera.height; ++y)
    for (int x = 0; x < scene.camera.width; ++x)
      rays.push_back(generate_camera_ray(scene.camera, x, y, glm::vec2(0.5f)));
  Pcg32 random(12345u);  // the kit's generator: the same sequence on every platform
  for (int i = 0; i < 20000; ++i) {
    Ray ray;
    ray.origin = scene_box.min + testkit::random_vec3(random, 0.0f, 1.0f) * (scene_box.max - scene_box.min);
    ray.direction = testkit::random_vec3(random, -1.0f, 1.0f);
    if (i % 2 == 1) ray.t_max = random.next_float() * 200.0f;  // shadow rays stop short
    rays.push_back(ray);
  }
  int hits = 0, differing = 0;
  for (const Ray& ray : rays) {
    const std::optional<SurfaceHit> expected = by_calls.intersect(ray), got = inlined.intersect(ray);
    const bool expected_occluded = by_calls.occluded(ray), got_occluded = inlined.occluded(ray);
    hits += expected.has_value();
    const bool same = expected.has_value() == got.has_value() && expected_occluded == got_occluded &&
                      (!expected || std::memcmp(&expected->t_hit, &got->t_hit, sizeof(float)) == 0);
    if (!same && ++differing <= 5)
      ADD_FAILURE() << scene_file << ", ray from " << ray.origin << " along " << ray.direction << " to t "
                    << ray.t_max << ": one tree " << (got ? got->t_hit : -1.0f) << " occluded " << got_occluded
                    << ", by calls " << (expected ? expected->t_hit : -1.0f) << " occluded " << expected_occluded;
  }
  EXPECT_EQ(differing, 0) << scene_file << " over " << rays.size() << " rays";
  EXPECT_GT(hits, static_cast<int>(rays.size()) / 4) << scene_file << ": rays that hit something";
  // Every triangle goes through the own tree (which counts nothing): what is tested one by one,
  // or through a tree over the objects, is the spheres at most.
  (void)SceneGeometry::take_thread_work();
  for (const Ray& ray : rays) {
    (void)inlined.intersect(ray);
    (void)inlined.occluded(ray);
  }
  const SceneGeometry::Work work = SceneGeometry::take_thread_work();
  EXPECT_LE(work.primitives, 2 * rays.size() * scene.spheres.size())
      << scene_file << ": primitives tested beside the own tree, over " << rays.size() << " rays";
}

// Counts camera rays, from whichever thread asks (TellsTheCallerOnceWhenItsWorkersHaveStarted).
std::atomic<int> camera_rays_asked{0};
Ray counting_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  ++camera_rays_asked;
  return generate_camera_ray(camera, pixel_x, pixel_y, position_in_pixel);
}

TEST(Render, TellsTheCallerOnceWhenItsWorkersHaveStarted) {
  // raylab render starts loading the image I/O from this call (render.h: a thread cannot be
  // created while another is inside dlopen, so the workers must exist first). Called before
  // them, the callback would wait here for a camera ray that no worker asks for.
  Scene scene = load_scene(source_path("scenes/whitted.json"));
  scene.camera.width = 32;
  scene.camera.height = 24;
  for (const int threads : {1, 2}) {
    RenderSettings settings;
    settings.threads = threads;
    settings.tracing.camera_ray = counting_camera_ray;
    camera_rays_asked = 0;
    int calls = 0;
    bool workers_ran = false;
    std::thread::id caller;
    settings.on_workers_started = [&] {
      ++calls;
      caller = std::this_thread::get_id();
      // (Not a time limit on the render: only so that a callback called too early fails
      // instead of waiting for ever.)
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
      while (camera_rays_asked == 0 && std::chrono::steady_clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      workers_ran = camera_rays_asked > 0;
    };
    (void)render(scene, settings);
    EXPECT_EQ(calls, 1) << threads << " threads";
    EXPECT_EQ(caller, std::this_thread::get_id()) << threads << " threads: called from another thread";
    EXPECT_TRUE(workers_ran) << threads << " threads: called before any worker ran";
  }
}

TEST(Render, ReferenceOwnTreeFindsTheSameHits) {
  for (const TriangleTreeBuilder tree : {&reference::build_four_wide_tree, &reference::build_fast_tree}) {
    expect_same_hits_with_own_tree("scenes/bunny.json", tree);    // one mesh
    expect_same_hits_with_own_tree("scenes/cornell.json", tree);  // 8 meshes, no spheres
    // Spheres beside the merged triangles: tested one by one (2), under a tree over the objects (4).
    expect_same_hits_with_own_tree("scenes/cornell_specular.json", tree);
    expect_same_hits_with_own_tree("scenes/mis_plates.json", tree);
  }
}

TEST(Render, ReferenceOwnTreeGivesTheSameImage) {
  // raylab-reference's geometry (one tree, inlined triangle tests) renders the picture of a
  // call per triangle: bit for bit for the bunny (camera rays, shadow rays and reflections,
  // no ties on its mesh); for the Cornell box's paths up to a path that met a tie somewhere
  // (a different triangle at the same t gives a point an ulp away, and the path goes on from
  // there): at most 1% of the pixels, each within 1% of its value.
  for (const std::string scene_file : {"scenes/bunny.json", "scenes/cornell.json"})
  for (const TriangleTreeBuilder tree : {&reference::build_four_wide_tree, &reference::build_fast_tree}) {
    SCOPED_TRACE(tree == &reference::build_fast_tree && reference::eight_wide_tree_runs_here() ? "the 8-wide tree"
                                                                                               : "the 4-wide tree");
    Scene scene = load_scene(source_path(scene_file));
    scene.camera.width = 64;
    scene.camera.height = 48;
    RenderSettings by_calls;
    by_calls.integrator = *integrator_from_name(scene.integrator);
    by_calls.max_depth = scene.max_depth;
    by_calls.samples_per_pixel = scene_file == "scenes/bunny.json" ? 1 : 4;
    RenderSettings inlined = by_calls;
    inlined.tracing.own_tree = tree;
    const Image expected = render(scene, by_calls);
    const Image got = render(scene, inlined);
    const int allowed = scene_file == "scenes/bunny.json" ? 0 : 64 * 48 / 100;
    int differing = 0, not_close = 0;
    for (int y = 0; y < expected.height(); ++y)
      for (int x = 0; x < expected.width(); ++x) {
        const glm::vec3 a = got.at(x, y), b = expected.at(x, y);
        if (std::memcmp(&a, &b, sizeof(glm::vec3)) == 0) continue;
        ++differing;
        // (false for NaN)
        const bool close = glm::all(glm::lessThanEqual(glm::abs(a - b), 0.01f * glm::abs(b) + 1e-6f));
        not_close += close ? 0 : 1;
        if ((allowed == 0 || !close) && differing + not_close <= 6)
          ADD_FAILURE() << scene_file << ", pixel (" << x << ", " << y << "): one tree " << a << ", by calls " << b;
      }
    EXPECT_LE(differing, allowed) << scene_file;
    EXPECT_EQ(not_close, 0) << scene_file << ": pixels more than 1% off";
    int not_background = 0;
    for (const glm::vec3& pixel : got.pixels()) not_background += pixel != scene.background;
    EXPECT_GT(not_background, 64 * 48 / 10) << scene_file << ": pixels other than the background";
  }
}

TEST(RussianRoulette, ReadsAProbabilityOrAutoAndNothingElse) {
  ASSERT_TRUE(RussianRoulette::from_text("auto"));
  EXPECT_TRUE(RussianRoulette::from_text("auto")->by_throughput);
  for (const char* text : {"0.8", "1", "0.001"}) {
    const std::optional<RussianRoulette> roulette = RussianRoulette::from_text(text);
    ASSERT_TRUE(roulette) << text;
    EXPECT_FALSE(roulette->by_throughput) << text;
    EXPECT_EQ(roulette->probability, std::stof(text)) << text;
  }
  for (const char* text : {"", "0", "-0.5", "1.5", "0.0009", "nan", "inf", "0.8x", "often", "Auto", "1e99", " 0.8",
                           "0.8 ", " auto"})
    EXPECT_FALSE(RussianRoulette::from_text(text)) << "'" << text << "' read as a roulette";
}

TEST(RussianRoulette, ByTheThroughputGoesOnAtTheFirstTwoSurfacesThenByTheLargestChannel) {
  const Scene scene = load_scene(source_path("scenes/furnace.json"));
  const SceneGeometry geometry(scene);
  const RenderContext fixed(scene, geometry, 5, Skips{}, RussianRoulette{0.8f, false});
  const RenderContext by_throughput(scene, geometry, 5, Skips{}, RussianRoulette{1.0f, true});
  for (int depth = 0; depth < 5; ++depth) {
    EXPECT_EQ(fixed.continue_probability(depth, glm::vec3(0.1f)), 0.8f) << "a fixed probability at depth " << depth;
    EXPECT_EQ(by_throughput.continue_probability(depth, glm::vec3(0.1f, 0.3f, 0.2f)), depth < 2 ? 1.0f : 0.3f)
        << "depth " << depth;
  }
  EXPECT_EQ(by_throughput.continue_probability(2, glm::vec3(3.0f, 0.1f, 0.0f)), 1.0f) << "at most 1";
  EXPECT_EQ(by_throughput.continue_probability(7, glm::vec3(1e-6f)), 0.05f) << "at least 0.05";
  for (const float probability : {0.0f, -1.0f, 1.5f, std::nanf("")})
    EXPECT_THROW(RenderContext(scene, geometry, 5, Skips{}, RussianRoulette{probability, false}), std::invalid_argument)
        << "a fixed probability of " << probability;
}

// The furnace (scenes/furnace.json): every pixel is 1 / (1 - 0.5) = 2 (minus 0.5^32 / 0.5 for
// paths cut at max_depth 30). With --roulette auto the reference path tracer must keep that
// expectation; its roulette adds noise (without roulette, every sample of the furnace is the same).
TEST(Render, RouletteByThroughputKeepsTheFurnaceAtTwo) {
  Scene scene = load_scene(source_path("scenes/furnace.json"));
  scene.camera.width = scene.camera.height = 16;
  RenderSettings settings;
  settings.integrator = IntegratorKind::Path;
  settings.samples_per_pixel = 16;
  settings.max_depth = scene.max_depth;
  settings.roulette = RussianRoulette{1.0f, true};
  settings.seed = 5;
  const Image image = render(scene, settings);
  // The t-test of the 256 pixel means, independent samples of the same value (one channel: the
  // furnace is grey). A correct path tracer fails it with probability 1e-5; the seed is fixed,
  // so the verdict never changes.
  std::vector<double> pixel_means;
  for (const glm::vec3& pixel : image.pixels()) pixel_means.push_back(pixel.x);
  const double expected = (1.0 - std::pow(0.5, 32)) / 0.5;
  const testkit::MeanTestResult result = testkit::mean_test(pixel_means, expected, 1e-5);
  ASSERT_GT(result.standard_error, 1e-4) << "no noise: the roulette stopped no path";
  EXPECT_TRUE(result.passed) << result.describe();
  EXPECT_LT(result.standard_error, 0.02) << "the mean should be known to a few hundredths";
}

// allot_samples_by_noise (render.h): where --spp-by-noise puts the samples after the pilot.
TEST(SamplesByNoise, ShareTheWholeBudgetByTheNoiseAroundEachPixelNotItsOwn) {
  constexpr int kWidth = 24, kHeight = 16;
  const auto total = [](const std::vector<std::uint32_t>& shares) {
    std::uint64_t sum = 0;
    for (const std::uint32_t share : shares) sum += share;
    return sum;
  };
  // Nothing noisy: every pixel the average (the rest shared equally).
  std::vector<float> noise(kWidth * kHeight, 0.0f);
  for (const int average : {2, 3, 7}) {
    const std::vector<std::uint32_t> shares = allot_samples_by_noise(noise, kWidth, kHeight, average, 2);
    for (const std::uint32_t share : shares) ASSERT_EQ(share, static_cast<std::uint32_t>(average));
  }
  // The left half noisy, the right half quiet: the left half takes more, every pixel at least
  // the pilot, and the total is the budget to the sample.
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth / 2; ++x) noise[y * kWidth + x] = 0.25f;
  std::vector<std::uint32_t> shares = allot_samples_by_noise(noise, kWidth, kHeight, 5, 2);
  EXPECT_EQ(total(shares), 5u * kWidth * kHeight);
  for (const std::uint32_t share : shares) EXPECT_GE(share, 2u);
  EXPECT_GT(shares[4 * kWidth + 2], 5u) << "deep in the noisy half";
  EXPECT_EQ(shares[4 * kWidth + kWidth - 2], 2u) << "deep in the quiet half: the pilot alone";
  // A pixel's own noise does not raise its count (its neighbours' does): one noisy pixel in a
  // quiet image keeps the pilot, while the pixels around it take the rest.
  std::fill(noise.begin(), noise.end(), 0.0f);
  noise[8 * kWidth + 12] = 1.0f;
  shares = allot_samples_by_noise(noise, kWidth, kHeight, 4, 2);
  EXPECT_EQ(shares[8 * kWidth + 12], 2u) << "the noisy pixel itself";
  EXPECT_GT(shares[8 * kWidth + 13], 4u) << "its neighbour";
  EXPECT_GT(shares[5 * kWidth + 9], 4u) << "3 rows and columns away";
  EXPECT_EQ(shares[4 * kWidth + 12], 2u) << "4 rows away: out of reach";
  EXPECT_EQ(total(shares), 4u * kWidth * kHeight);
  // One noisy patch in a large quiet image: its pixels take at most 16 times the average, and
  // the rest of the budget goes to every pixel alike (at most 1 more each, with rounding).
  std::vector<float> large(200 * 200, 0.0f);
  large[100 * 200 + 100] = 1.0f;
  shares = allot_samples_by_noise(large, 200, 200, 3, 2);
  EXPECT_EQ(*std::max_element(shares.begin(), shares.end()), 16u * 3u + 1u);
  EXPECT_LE(shares[0], 3u);
  EXPECT_EQ(total(shares), 3u * 200 * 200);
  // Noise that is not a finite positive number counts as none.
  std::fill(noise.begin(), noise.end(), std::numeric_limits<float>::quiet_NaN());
  noise[0] = std::numeric_limits<float>::infinity();
  noise[1] = -1.0f;
  for (const std::uint32_t share : allot_samples_by_noise(noise, kWidth, kHeight, 4, 2)) ASSERT_EQ(share, 4u);
  EXPECT_THROW((void)allot_samples_by_noise(noise, kWidth + 1, kHeight, 4, 2), std::invalid_argument);
  EXPECT_THROW((void)allot_samples_by_noise(noise, kWidth, kHeight, 1, 2), std::invalid_argument);
  EXPECT_THROW((void)allot_samples_by_noise(noise, kWidth, kHeight, 4, 0), std::invalid_argument);
}

TEST(SamplesByNoise, SpendTheBudgetWhereThePictureIsNoisyTheSameAtAnyThreadCount) {
  Scene scene = load_scene(source_path("scenes/cornell.json"));
  scene.camera.width = scene.camera.height = 32;
  RenderSettings settings;
  settings.integrator = IntegratorKind::Path;
  settings.max_depth = scene.max_depth;
  settings.roulette = RussianRoulette{1.0f, true};
  settings.samples_per_pixel = 6;
  settings.samples_by_noise = true;
  settings.track_variance = true;
  settings.threads = 2;
  const RenderOutput two = render_with_variance(scene, settings);
  settings.threads = 1;
  const RenderOutput one = render_with_variance(scene, settings);
  EXPECT_EQ(one.mean.pixels(), two.mean.pixels()) << "by noise: 1 and 2 threads differ";
  EXPECT_EQ(one.variance_of_mean.pixels(), two.variance_of_mean.pixels());
  EXPECT_EQ(one.sample_rate.pixels(), two.sample_rate.pixels()) << "by noise: 1 and 2 threads took other samples";
  // Every pixel at least the pilot, whole samples, 6 per pixel on average exactly, and spread:
  // some pixels keep the pilot, a tenth or more take above the average.
  double samples = 0.0;
  int pilot_only = 0, above_average = 0;
  for (std::size_t i = 0; i < one.sample_rate.pixels().size(); ++i) {
    const float count = one.sample_rate.pixels()[i].x * 6.0f;
    ASSERT_EQ(count, std::round(count));
    EXPECT_GE(count, static_cast<float>(kPilotSamples));
    samples += count;
    pilot_only += count == kPilotSamples;
    above_average += count > 6.0f;
  }
  EXPECT_EQ(samples, 6.0 * 32 * 32);
  EXPECT_GT(pilot_only, 0);
  EXPECT_GT(above_average, 32 * 32 / 10);

  // At most 2 samples on average: nothing left to share, every pixel takes them all.
  settings.samples_per_pixel = 2;
  const RenderOutput pilot_only_render = render_with_variance(scene, settings);
  for (const glm::vec3& rate : pilot_only_render.sample_rate.pixels()) ASSERT_EQ(rate.x, 1.0f);
  settings.adaptive_tolerance = 0.05f;
  EXPECT_THROW((void)render(scene, settings), std::invalid_argument) << "with adaptive sampling";
}

// --spp-by-noise keeps each pixel's mean an unbiased estimate: a pixel's count comes from the
// pilot samples of the pixels around it, not its own. The furnace made dimmer (emission 0.25:
// every pixel 0.25 / (1 - 0.5) = 0.5, less 0.25 x 0.5^32 / 0.5 for paths cut at 30 bounces), so
// that its samples, 0.5 on average and spread by the roulette, are not all clamped away: the
// pixels' counts then vary from 2 to several times the average by chance. (Shares by each pixel's
// own pilot noise instead fail it: mean 0.4826, t = -35. A pixel whose first samples happened to
// be far apart takes more samples, which pull its mean towards the middle.)
TEST(SamplesByNoise, KeepTheFurnacesMean) {
  Scene scene = load_scene(source_path("scenes/furnace.json"));
  scene.camera.width = scene.camera.height = 32;
  for (Material& material : scene.materials) material.emission *= 0.25f;
  RenderSettings settings;
  settings.integrator = IntegratorKind::Path;
  settings.samples_per_pixel = 4;
  settings.samples_by_noise = true;
  settings.max_depth = scene.max_depth;
  settings.roulette = RussianRoulette{1.0f, true};
  settings.seed = 7;
  const RenderOutput output = render_with_variance(scene, settings);
  float fewest = 1e9f, most = 0.0f;
  for (const glm::vec3& rate : output.sample_rate.pixels()) {
    fewest = std::min(fewest, rate.x * 4.0f);
    most = std::max(most, rate.x * 4.0f);
  }
  EXPECT_EQ(fewest, 2.0f);
  EXPECT_GE(most, 6.0f) << "the counts should vary";
  // The t-test of the 1,024 pixel means (independent, of the same expectation; a correct
  // renderer fails it with probability 1e-5, and the seed is fixed).
  std::vector<double> pixel_means;
  for (const glm::vec3& pixel : output.mean.pixels()) pixel_means.push_back(pixel.x);
  const double expected = 0.25 * (1.0 - std::pow(0.5, 32)) / 0.5;
  const testkit::MeanTestResult result = testkit::mean_test(pixel_means, expected, 1e-5);
  EXPECT_TRUE(result.passed) << result.describe();
  EXPECT_LT(result.standard_error, 0.01);
}

TEST(Render, EmptySceneIsAllBackground) {
  const Scene scene = parse_scene(R"({
    "camera": { "width": 9, "height": 7 },
    "background": [0.25, 0.5, 0.75],
    "objects": []
  })", "empty_scene", ".");
  const Image image = render_with_threads(scene, 2);
  ASSERT_EQ(image.width(), 9);
  ASSERT_EQ(image.height(), 7);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      EXPECT_EQ(image.at(x, y), scene.background) << "pixel (" << x << ", " << y << ")";
}

// The floor point seen by pixel (x, y): where the camera ray meets the plane y = floor_y,
// computed in double. Returns false if the ray does not go down to it.
bool floor_point_of_pixel(const Camera& camera, int x, int y, double floor_y, glm::dvec3& point) {
  const Ray ray = generate_camera_ray(camera, x, y);
  const glm::dvec3 origin(ray.origin), direction(ray.direction);
  if (direction.y >= 0.0) return false;
  point = origin + (floor_y - origin.y) / direction.y * direction;
  return true;
}

// Distance from `center` to the segment from `a` to `b`.
double distance_to_segment(const glm::dvec3& center, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double s = std::clamp(glm::dot(center - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(a + s * ab - center);
}

TEST(Render, OpaqueSphereCastsAShadowWithoutLeaks) {
  // A camera looks straight down at a white floor (y = 0). A light at (4, 2, 0) shines past
  // an opaque sphere at (2, 1, 0), radius 0.5, straight onto the floor around (0, 0, 0).
  // Every floor pixel is classified in double precision: its segment to the light passes
  // through the sphere (shadow: must be exactly black, as ks = 0 and there is no ambient term)
  // or clearly misses it (lit: must be bright). Pixels within 0.02 of the shadow's edge, and
  // pixels that see the sphere itself, are skipped.
  const std::string text = R"({
    "camera": { "position": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, -1],
                "fov_y_degrees": 90, "width": 41, "height": 41 },
    "background": [0.3, 0.3, 0.3],
    "materials": {
      "white": { "type": "diffuse_glossy", "diffuse_color": [1, 1, 1], "kd": 1, "ks": 0 }
    },
    "objects": [
      { "type": "sphere", "center": [2, 1, 0], "radius": 0.5, "material": "white" },
      { "type": "mesh", "positions": [[-20, 0, -20], [23, 0, -20], [23, 0, 21], [-20, 0, 21]],
        "triangles": [[0, 1, 2], [0, 2, 3]], "material": "white" }
    ],
    "lights": [ { "type": "point", "position": [4, 2, 0], "intensity": 1 } ]
  })";
  const Scene scene = parse_scene(text, "shadow_scene", ".");
  const Image image = render_with_threads(scene, 2);
  const glm::dvec3 light(4.0, 2.0, 0.0), sphere_center(2.0, 1.0, 0.0);
  constexpr double kRadius = 0.5, kMargin = 0.02;

  int shadowed = 0, lit = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      glm::dvec3 floor_point;
      ASSERT_TRUE(floor_point_of_pixel(scene.camera, x, y, 0.0, floor_point));
      const Ray camera_ray = generate_camera_ray(scene.camera, x, y);
      if (distance_to_segment(sphere_center, glm::dvec3(camera_ray.origin), floor_point) <
          kRadius + kMargin)
        continue;  // the camera sees the sphere (or nearly) here
      const double clearance = distance_to_segment(sphere_center, floor_point, light) - kRadius;
      const glm::vec3 pixel = image.at(x, y);
      if (clearance < -kMargin) {
        ++shadowed;
        EXPECT_EQ(pixel, glm::vec3(0.0f))
            << "light leak: pixel (" << x << ", " << y << ") sees floor point " << glm::vec3(floor_point)
            << ", whose path to the light at " << glm::vec3(light) << " passes "
            << -clearance << " inside the sphere; expected black";
      } else if (clearance > kMargin) {
        ++lit;
        EXPECT_GT(brightest_channel(pixel), 0.01f)
            << "pixel (" << x << ", " << y << ") sees floor point " << glm::vec3(floor_point)
            << ", which the light reaches with " << clearance << " to spare; got " << pixel;
      }
    }
  // The set-up must produce both kinds of pixel, including the one under the centre.
  EXPECT_GT(shadowed, 10) << "too few shadowed pixels to test";
  EXPECT_GT(lit, 100) << "too few lit pixels to test";
  EXPECT_EQ(image.at(20, 20), glm::vec3(0.0f)) << "the centre pixel sees (0, 0, 0), in full shadow";
}

TEST(Render, NoShadowAcneAtGrazingLight) {
  // A tilted floor whose points cannot be represented exactly in float, lit by a distant light
  // about 3 degrees above its plane. A shadow ray started exactly at the computed hit point
  // would find the floor itself (at t near 0) for many pixels and draw them black: shadow
  // acne. The renderer's offset origins must keep every pixel lit.
  const glm::dvec3 u = glm::normalize(glm::dvec3(1.0, 0.3, 0.1));       // in the plane
  const glm::dvec3 v = glm::normalize(glm::cross(glm::dvec3(0.2, 0.1, 1.0), u));  // in the plane
  const glm::dvec3 normal = glm::normalize(glm::cross(u, v));
  const glm::dvec3 centre(0.37, -1.29, -3.71);
  const double elevation = 3.0 * 3.14159265358979 / 180.0;
  const glm::dvec3 light = centre + 1000.0 * (std::cos(elevation) * u + std::sin(elevation) * normal);
  const glm::dvec3 eye = centre + 4.0 * normal + 0.5 * v;
  auto corner = [&](double a, double b) { return centre + a * u + b * v; };
  auto json_vec = [](const glm::dvec3& p) {
    std::ostringstream out;
    out.precision(17);
    out << '[' << p.x << ", " << p.y << ", " << p.z << ']';
    return out.str();
  };
  const std::string text = R"({
    "camera": { "position": )" + json_vec(eye) + R"(, "look_at": )" + json_vec(centre) +
      R"(, "up": [0, 1, 0], "fov_y_degrees": 60, "width": 48, "height": 48 },
    "background": [0, 0, 0],
    "materials": { "white": { "type": "diffuse_glossy", "diffuse_color": [1, 1, 1], "kd": 1, "ks": 0 } },
    "objects": [
      { "type": "mesh", "material": "white",
        "positions": [)" + json_vec(corner(-50, -50)) + ", " + json_vec(corner(50, -50)) + ", " +
      json_vec(corner(50, 50)) + ", " + json_vec(corner(-50, 50)) + R"(],
        "triangles": [[0, 1, 2], [0, 2, 3]] }
    ],
    "lights": [ { "type": "point", "position": )" + json_vec(light) + R"(, "intensity": 1 } ]
  })";
  const Scene scene = parse_scene(text, "grazing_light_scene", ".");
  const Image image = render_with_threads(scene, 2);
  // Lit means about sin(3 degrees) = 0.05; black means the floor shadowed itself.
  int black = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (!(brightest_channel(image.at(x, y)) > 0.02f) && ++black <= 5)
        ADD_FAILURE() << "shadow acne: pixel (" << x << ", " << y << ") is " << image.at(x, y)
                      << "; every pixel sees the lit floor";
  EXPECT_EQ(black, 0) << "black pixels out of " << image.width() * image.height()
                      << "\nscene: " << text;

  // The scene must be hard enough to matter: from the exact hit points, without the offset,
  // some shadow rays should hit the floor they start on.
  const SceneGeometry geometry(scene);
  int self_hits = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const auto hit = geometry.intersect(generate_camera_ray(scene.camera, x, y));
      ASSERT_TRUE(hit.has_value()) << "pixel (" << x << ", " << y << ") must see the floor";
      Ray shadow;
      shadow.origin = hit->point;
      shadow.direction = glm::vec3(light) - hit->point;
      shadow.t_max = 1.0f - 1e-4f;
      self_hits += geometry.occluded(shadow);
    }
  EXPECT_GT(self_hits, 0) << "no pixel self-shadows without an offset: the test proves nothing";
}

}  // namespace
}  // namespace raylab
