// The sampler, the film and the anti-aliased render: numbers that depend only on (pixel,
// sample index, dimension), stratified over a pixel's samples; means and variances of the
// mean as defined in film.h; more samples per pixel, same bytes at any thread count.
#include "raylab/film.h"
#include "raylab/integrator.h"
#include "raylab/render.h"
#include "raylab/sampler.h"
#include "raylab/scene_loader.h"

#include "test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace raylab {
namespace {

using testing::source_path;

// The first `dimensions` values (1D draws) of one pixel sample.
std::vector<float> draw(Sampler& sampler, int x, int y, int index, int dimensions) {
  sampler.start_pixel_sample(x, y, index);
  std::vector<float> values;
  for (int d = 0; d < dimensions; ++d) values.push_back(sampler.get_1d());
  return values;
}

TEST(Sampler, NumbersDependOnlyOnPixelSampleIndexAndDimension) {
  // Visiting pixels and samples in another order (another thread's tile order) must give
  // the same numbers bit for bit.
  Sampler forward(8), backward(8);
  std::vector<std::vector<float>> first, second;
  for (int index = 0; index < 8; ++index) first.push_back(draw(forward, 5, 7, index, 6));
  (void)draw(backward, 100, 3, 2, 9);  // some other pixel first
  for (int index = 7; index >= 0; --index) second.push_back(draw(backward, 5, 7, index, 6));
  std::reverse(second.begin(), second.end());
  EXPECT_EQ(first, second);
  // Another pixel, another seed: other numbers.
  Sampler other_seed(8, 1);
  EXPECT_NE(draw(forward, 5, 7, 3, 6), draw(forward, 6, 7, 3, 6));
  EXPECT_NE(draw(forward, 5, 7, 3, 6), draw(other_seed, 5, 7, 3, 6));
}

TEST(Sampler, EveryPowerOfTwoPrefixOfOneDimensionFallsOneInEachStratum) {
  // Progressive: the first 2^k samples of a pixel put one value in each of 2^k equal
  // intervals, whatever the sample count, at every dimension.
  Sampler sampler(64);
  for (int dimension = 0; dimension < 6; ++dimension)
    for (int prefix = 1; prefix <= 64; prefix *= 2) {
      std::set<int> strata;
      for (int index = 0; index < prefix; ++index) {
        const float value = draw(sampler, 2, 9, index, dimension + 1).back();
        ASSERT_GE(value, 0.0f);
        ASSERT_LT(value, 1.0f);
        strata.insert(static_cast<int>(value * static_cast<float>(prefix)));
      }
      EXPECT_EQ(strata.size(), static_cast<std::size_t>(prefix)) << prefix << " samples, dimension " << dimension;
    }
}

TEST(Sampler, TwoDimensionalPointsFillEveryGridOfTheirCount) {
  // The first 16 (64, 4096) points of a 2D dimension: one in each cell of every grid of
  // 2^a x 2^b cells with 2^(a + b) cells as many as the points (1 x 16, 2 x 8, 4 x 4, 8 x 2,
  // 16 x 1), a (0, k, 2)-net; so the x and y projections are stratified too.
  Sampler sampler(4096);
  for (int dimension : {0, 3}) {
    for (int log2_count : {4, 6, 12}) {  // 2^12: the direction numbers up to v_11 at work
      const int count = 1 << log2_count;
      std::vector<glm::vec2> points;
      for (int index = 0; index < count; ++index) {
        sampler.start_pixel_sample(3, 4, index);
        for (int d = 0; d < dimension; ++d) (void)sampler.get_1d();
        const glm::vec2 value = sampler.get_2d();
        ASSERT_TRUE(value.x >= 0.0f && value.x < 1.0f && value.y >= 0.0f && value.y < 1.0f) << value;
        points.push_back(value);
      }
      for (int a = 0; a <= log2_count; ++a) {
        const int columns = 1 << a, rows = count / columns;
        std::set<int> cells;
        for (const glm::vec2& p : points)
          cells.insert(static_cast<int>(p.x * static_cast<float>(columns)) * rows + static_cast<int>(p.y * static_cast<float>(rows)));
        EXPECT_EQ(cells.size(), static_cast<std::size_t>(count))
            << count << " points, " << columns << " x " << rows << " cells, after " << dimension << " 1D draws";
      }
    }
  }
}

TEST(Sampler, ASampleHasTheSameNumbersAtAnySampleCountAboveOne) {
  // The count only says where a 1-sample render aims (the centre); a pixel's sample 3 is the
  // same at --spp 4 and --spp 64, so a pixel that stops early keeps a stratified prefix.
  Sampler four(4), many(64);
  for (int index = 0; index < 4; ++index) EXPECT_EQ(draw(four, 8, 1, index, 5), draw(many, 8, 1, index, 5));
}

TEST(Sampler, DimensionsAreNotCorrelatedWithEachOther) {
  // Each dimension shuffles the pixel's samples its own way, so a sample's value in one
  // dimension says little about its value in another. Per pixel of 16 samples, 8 are below 1/2
  // in each dimension. The shuffles pair the samples in 8 couples (indices 2i and 2i + 1), one of
  // each couple below 1/2 in each dimension; if it is the same one with chance 1/2, as a model,
  // the samples below 1/2 in both number Binomial(8, 1/2): 4 on average, a variance of 2 (over
  // 800 pixels, 2 +- 0.09). Measured, the six pairs below give 1.91 to 2.17. Without the shuffle
  // two dimensions of the same scrambled sequence share their first digit up to a flip: 8 or 0,
  // a variance of 16. (This sees only a correlation of the first digit.)
  // Draws per sample: 1D, 1D, 2D (x, y), 1D, 1D; pairs of 1D draws, and 1D against 2D coordinates.
  Sampler sampler(16);
  const auto draws = [&sampler](int pixel, int index) {
    sampler.start_pixel_sample(pixel, 1, index);
    std::vector<float> values;
    values.push_back(sampler.get_1d());
    values.push_back(sampler.get_1d());
    const glm::vec2 point = sampler.get_2d();
    values.push_back(point.x);
    values.push_back(point.y);
    values.push_back(sampler.get_1d());
    values.push_back(sampler.get_1d());
    return values;
  };
  for (const auto& pair : {std::pair<std::size_t, std::size_t>{0, 1}, {0, 5}, {4, 5}, {1, 2}, {1, 3}, {3, 4}}) {
    double squared_deviation = 0.0;
    const int pixels = 800;
    for (int pixel = 0; pixel < pixels; ++pixel) {
      int both_low = 0;
      for (int index = 0; index < 16; ++index) {
        const std::vector<float> values = draws(pixel, index);
        both_low += values[pair.first] < 0.5f && values[pair.second] < 0.5f;
      }
      squared_deviation += (both_low - 4) * (both_low - 4);
    }
    EXPECT_LT(squared_deviation / pixels, 3.0) << "draws " << pair.first << " and " << pair.second;
  }
}

TEST(Sampler, StratifiedPixelPointsEstimateAnAreaBetterThanIndependentOnes) {
  // The fraction of the pixel below the diagonal y < x (exactly 1/2), from 16 points per
  // pixel over many pixels: the stratified points' mean squared error is far below that of
  // independent uniform points (1/16 * 1/4 = 1/64 per pixel).
  Sampler sampler(16);
  double squared_error = 0.0;
  const int pixels = 400;
  for (int pixel = 0; pixel < pixels; ++pixel) {
    int below = 0;
    for (int index = 0; index < 16; ++index) {
      sampler.start_pixel_sample(pixel, 0, index);
      const glm::vec2 point = sampler.get_pixel_2d();
      below += point.y < point.x;
    }
    const double error = below / 16.0 - 0.5;
    squared_error += error * error;
  }
  EXPECT_LT(squared_error / pixels, (1.0 / 64.0) / 4.0);
}

TEST(Sampler, OneSamplePerPixelAimsAtTheCentre) {
  Sampler sampler(1);
  sampler.start_pixel_sample(10, 20, 0);
  EXPECT_EQ(sampler.get_pixel_2d(), glm::vec2(0.5f));
  EXPECT_EQ(sampler.dimension(), 1);
  EXPECT_THROW(Sampler(0), std::invalid_argument);
}

TEST(Sampler, ConstantGivesItsNumbersAtEveryDimensionInAnyOrder) {
  // The grader replays a path with chosen numbers (stage 09b): whatever order the code draws in,
  // every 1D number is u1 and every 2D number u2.
  Sampler sampler = Sampler::constant(0.25f, glm::vec2(0.1f, 0.9f));
  sampler.start_pixel_sample(3, 4, 0);
  EXPECT_EQ(sampler.get_pixel_2d(), glm::vec2(0.5f));
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(sampler.get_2d(), glm::vec2(0.1f, 0.9f));
    EXPECT_EQ(sampler.get_1d(), 0.25f);
  }
  EXPECT_EQ(sampler.dimension(), 11);
  EXPECT_THROW(Sampler::constant(1.0f, glm::vec2(0.5f)), std::invalid_argument);
  EXPECT_THROW(Sampler::constant(0.5f, glm::vec2(-0.1f, 0.5f)), std::invalid_argument);
}

// A dimension's numbers as owen_sobol.h defines them, one at a time: the pixel's key, the
// dimension's key, then dimension_numbers.
glm::vec2 numbers_one_at_a_time(int x, int y, int index, int dimension, std::uint64_t seed) {
  const std::uint64_t pixel_key =
      owen_sobol::pixel_key(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), seed);
  glm::vec2 numbers;
  owen_sobol::dimension_numbers(owen_sobol::dimension_key(pixel_key, static_cast<std::uint32_t>(dimension)),
                                owen_sobol::reverse_bits(static_cast<std::uint32_t>(index)), numbers.x, numbers.y);
  return numbers;
}

TEST(Sampler, SixteenDimensionsAtOnceGiveTheNumbersOfOneAtATime) {
  // The sampler computes blocks of eight dimensions' seeds, and two blocks' numbers, together (with
  // AVX2 where the CPU has it): the same, bit for bit, as one at a time, at every key, sample index
  // and dimension, also where the dimension's number wraps around 2^32.
  Pcg32 random(7, 11);
  const bool avx2 = [] {
    owen_sobol::BlockSeeds seeds;
    return owen_sobol::block_seeds_avx2(0, 0, seeds);
  }();
  if (!avx2) std::printf("(no AVX2 here: only the one-by-one way is checked)\n");
  constexpr int kBlock = owen_sobol::kBlockDimensions;
  constexpr int kAtOnce = owen_sobol::kDimensionsAtOnce;
  for (int trial = 0; trial < 20000; ++trial) {
    const std::uint64_t pixel_key = (static_cast<std::uint64_t>(random.next_uint32()) << 32u) | random.next_uint32();
    const std::uint32_t reversed_index = trial < 100 ? owen_sobol::reverse_bits(static_cast<std::uint32_t>(trial))
                                                     : random.next_uint32();
    // Two blocks, each from any dimension (the sampler's are consecutive, from a multiple of 16).
    std::uint32_t first_dimensions[2];
    for (std::uint32_t& first_dimension : first_dimensions)
      first_dimension =
          trial % 3 == 0 ? random.next_uint32() % 64 : (trial % 3 == 1 ? 0xfffffffcu : random.next_uint32());
    owen_sobol::BlockSeeds seeds[2], wide_seeds[2], avx2_seeds[2];
    for (int b = 0; b < 2; ++b) {
      owen_sobol::block_seeds_one_by_one(pixel_key, first_dimensions[b], seeds[b]);
      owen_sobol::block_seeds(pixel_key, first_dimensions[b], wide_seeds[b]);
      ASSERT_EQ(owen_sobol::block_seeds_avx2(pixel_key, first_dimensions[b], avx2_seeds[b]), avx2);
    }
    float first[kAtOnce], second[kAtOnce], wide_first[kAtOnce], wide_second[kAtOnce];
    float avx2_first[kAtOnce], avx2_second[kAtOnce];
    owen_sobol::fill_dimension_blocks_one_by_one(seeds[0], seeds[1], reversed_index, first, second);
    owen_sobol::fill_dimension_blocks(seeds[0], seeds[1], reversed_index, wide_first, wide_second);
    ASSERT_EQ(owen_sobol::fill_dimension_blocks_avx2(seeds[0], seeds[1], reversed_index, avx2_first, avx2_second),
              avx2);
    for (int i = 0; i < kAtOnce; ++i) {
      const int b = i / kBlock, lane = i % kBlock;
      const std::uint32_t dimension = first_dimensions[b] + static_cast<std::uint32_t>(lane);
      const std::uint64_t key = owen_sobol::dimension_key(pixel_key, dimension);
      const owen_sobol::DimensionSeeds expected_seeds(key);
      const std::string where = "trial " + std::to_string(trial) + ", dimension " + std::to_string(dimension);
      for (const owen_sobol::BlockSeeds* way : {&seeds[b], &wide_seeds[b], avx2 ? &avx2_seeds[b] : &seeds[b]}) {
        ASSERT_EQ(way->shuffle[lane], expected_seeds.shuffle) << where;
        ASSERT_EQ(way->first[lane], expected_seeds.first) << where;
        ASSERT_EQ(way->second[lane], expected_seeds.second) << where;
      }
      float expected_first = 0.0f, expected_second = 0.0f;
      owen_sobol::dimension_numbers(key, reversed_index, expected_first, expected_second);
      ASSERT_EQ(first[i], expected_first) << where;
      ASSERT_EQ(second[i], expected_second) << where;
      ASSERT_EQ(wide_first[i], expected_first) << where;
      ASSERT_EQ(wide_second[i], expected_second) << where;
      if (avx2) {
        ASSERT_EQ(avx2_first[i], expected_first) << where;
        ASSERT_EQ(avx2_second[i], expected_second) << where;
      }
    }
  }
  // Through the sampler, which keeps a pixel's seeds for its next samples: 1D and 2D draws in a
  // mixed order across the blocks' edges and past the seeds it keeps (dimension 64 on), a pixel
  // sample started again in the middle of a block, the skipped dimension of a 1-spp pixel centre,
  // samples of one pixel in turn and of pixels in turn, and a pixel come back to.
  const auto check_draws = [](Sampler& sampler, int x, int y, int index, int samples, int dimensions) {
    sampler.start_pixel_sample(x, y, index);
    const glm::vec2 pixel = sampler.get_pixel_2d();
    if (samples > 1) {
      EXPECT_EQ(pixel, numbers_one_at_a_time(x, y, index, 0, 5));
    } else {
      EXPECT_EQ(pixel, glm::vec2(0.5f));
    }
    for (int dimension = 1; dimension < dimensions; ++dimension) {
      const glm::vec2 expected = numbers_one_at_a_time(x, y, index, dimension, 5);
      if (dimension % 3 == 0) {
        ASSERT_EQ(sampler.get_2d(), expected) << "pixel " << x << ", " << y << " sample " << index << " dimension "
                                              << dimension;
      } else {
        ASSERT_EQ(sampler.get_1d(), expected.x) << "pixel " << x << ", " << y << " sample " << index
                                                << " dimension " << dimension;
      }
    }
  };
  for (const int samples : {1, 16}) {
    Sampler sampler(samples, 5);
    for (int index = 0; index < samples; ++index)  // pixels in turn
      for (const int x : {0, 3, 1000}) {
        check_draws(sampler, x, 9, index, samples, 30);
        sampler.start_pixel_sample(x, 10, index);  // another pixel, its block not drawn out
        ASSERT_EQ(sampler.get_1d(), numbers_one_at_a_time(x, 10, index, 0, 5).x);
      }
    for (const int x : {3, 4, 3})  // a pixel's samples in turn, as a render takes them
      for (int index = 0; index < samples; ++index) check_draws(sampler, x, 9, index, samples, 3 + 7 * index);
  }
  Sampler sampler(16, 5);
  for (int index = 0; index < 16; ++index) check_draws(sampler, 7, 2, index, 16, index % 2 ? 80 : 20);
  for (int index = 15; index >= 0; --index) check_draws(sampler, 7, 2, index, 16, 100);
  for (const int x : {8, 7})  // past the kept seeds at another pixel, then back
    for (int index = 0; index < 4; ++index) check_draws(sampler, x, 2, index, 16, 100);
}

TEST(Sampler, NumbersAreThoseTheImagesWereMadeWith) {
  // Every rendered image depends on the sampler's numbers: these, drawn by the sampler of
  // 295cc84 (one dimension hashed per draw), must not change when the way they are computed does.
  struct Pinned {
    int samples, x, y, index;
    std::uint64_t seed;
    glm::vec2 pixel;
    float first_1d;
    glm::vec2 first_2d, dimension_12;
  };
  const Pinned pinned[] = {
      {16, 0, 0, 0, 0, {0x1.32ec1p-2f, 0x1.12a74p-6f}, 0x1.ddbf56p-1f, {0x1.2dcba8p-2f, 0x1.389d38p-3f},
       {0x1.f1171ep-1f, 0x1.73d8fep-1f}},
      {16, 5, 7, 3, 0, {0x1.07d88p-7f, 0x1.882544p-1f}, 0x1.9281e4p-2f, {0x1.f2a87cp-1f, 0x1.5cc948p-2f},
       {0x1.89abcep-1f, 0x1.86f882p-1f}},
      {64, 1000, 9, 63, 5, {0x1.7f4c54p-2f, 0x1.cbf89p-3f}, 0x1.fc6478p-2f, {0x1.8aeaa4p-1f, 0x1.3cd14p-6f},
       {0x1.ab3c5ap-1f, 0x1.4baae8p-3f}},
      {4, 3, 2, 1, 2, {0x1.0d2c96p-1f, 0x1.73f7p-3f}, 0x1.d866cp-4f, {0x1.d87296p-1f, 0x1.63b9a8p-3f},
       {0x1.6d5312p-1f, 0x1.49fefp-3f}},
  };
  for (const Pinned& p : pinned) {
    Sampler sampler(p.samples, p.seed);
    sampler.start_pixel_sample(p.x, p.y, p.index);
    EXPECT_EQ(sampler.get_pixel_2d(), p.pixel);
    EXPECT_EQ(sampler.get_1d(), p.first_1d);
    EXPECT_EQ(sampler.get_2d(), p.first_2d);
    for (int i = 0; i < 9; ++i) (void)sampler.get_1d();
    EXPECT_EQ(sampler.get_2d(), p.dimension_12);
  }
}

TEST(Film, MeanAndVarianceOfTheMeanPerPixel) {
  Film film(2, 1, true);
  for (float value : {1.0f, 2.0f, 3.0f, 6.0f}) film.add_sample(0, 0, glm::vec3(value, 0.0f, -value));
  film.add_sample(1, 0, glm::vec3(0.1f, 0.2f, 0.3f));
  const Image mean = film.mean(), variance = film.variance_of_mean();
  // Samples 1, 2, 3, 6: mean 3, s^2 = (4 + 1 + 0 + 9) / 3 = 14 / 3, variance of the mean 14 / 12.
  EXPECT_TRUE(testing::vec3_near(mean.at(0, 0), glm::vec3(3.0f, 0.0f, -3.0f), 1e-6f));
  EXPECT_TRUE(testing::vec3_near(variance.at(0, 0), glm::vec3(14.0f / 12.0f, 0.0f, 14.0f / 12.0f), 1e-6f));
  // One sample: its mean is that sample exactly (the 1-spp image is unchanged), no variance.
  EXPECT_EQ(mean.at(1, 0), glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(variance.at(1, 0), glm::vec3(0.0f));
  EXPECT_EQ(film.sample_count(0, 0), 4u);
  EXPECT_THROW((void)Film(1, 1, false).variance_of_mean(), std::logic_error);
}

TEST(Render, MoreSamplesPerPixelSmoothEdgesAndKeepFlatAreasExact) {
  Scene scene = load_scene(source_path("scenes/whitted.json"));
  scene.camera.width = 64;
  scene.camera.height = 48;
  RenderSettings settings;
  settings.threads = 2;
  const Image one_sample = render(scene, settings);
  settings.samples_per_pixel = 9;
  settings.track_variance = true;
  const RenderOutput output = render_with_variance(scene, settings);
  const Image& nine = output.mean;
  const Image& variance = output.variance_of_mean;
  settings.threads = 1;
  const Image nine_one_thread = render(scene, settings);
  EXPECT_EQ(nine.pixels(), nine_one_thread.pixels()) << "9 spp: 1 and 2 threads differ";
  int flat = 0, edges = 0;
  for (int y = 0; y < scene.camera.height; ++y)
    for (int x = 0; x < scene.camera.width; ++x) {
      if (variance.at(x, y) == glm::vec3(0.0f)) {
        // Every sample saw the same colour: the mean is that colour (top rows: background).
        if (y == 0) {
          EXPECT_EQ(nine.at(x, y), one_sample.at(x, y)) << "pixel " << x << ", 0";
        }
        ++flat;
      } else {
        ++edges;
      }
    }
  EXPECT_GT(flat, scene.camera.width);  // at least the background row
  EXPECT_GT(edges, 10);                 // the spheres' outlines are no longer one colour
}

TEST(PixelConvergence, TheConfidenceIntervalRuleOnKnownSamples) {
  // 32 samples alternating 0 and 2 in green (illuminance 0 and 2 x 0.7152; the scale cancels):
  // mean 1, s^2 = (64 - 32) / 31, so the interval 1.96 s / sqrt(32) is 0.35203 of the mean.
  PixelConvergence pixel;
  for (int i = 0; i < 32; ++i) pixel.add(glm::vec3(0.0f, i % 2 ? 2.0f : 0.0f, 0.0f));
  EXPECT_EQ(pixel.count(), 32u);
  EXPECT_TRUE(pixel.converged(0.353));
  EXPECT_FALSE(pixel.converged(0.351));

  PixelConvergence constant;  // no spread: known after 2 samples, at any tolerance
  constant.add(glm::vec3(0.3f, 0.2f, 0.1f));
  EXPECT_FALSE(constant.converged(1.0)) << "one sample says nothing about the spread";
  constant.add(glm::vec3(0.3f, 0.2f, 0.1f));
  EXPECT_TRUE(constant.converged(1e-6));

  PixelConvergence black;  // only zeros so far: in a dim corner the light may not be found yet
  for (int i = 0; i < 64; ++i) black.add(glm::vec3(0.0f));
  EXPECT_FALSE(black.converged(1.0));
  black.add(glm::vec3(0.01f));  // then the rule as usual: a huge spread for this mean
  EXPECT_FALSE(black.converged(1.0));

  PixelConvergence broken;
  broken.add(glm::vec3(1.0f));
  broken.add(glm::vec3(std::nanf(""), 0.0f, 0.0f));
  broken.add(glm::vec3(1.0f));
  EXPECT_FALSE(broken.converged(1.0)) << "a NaN sample never counts as converged";

  // Red counts 0.2126, blue 0.0722: the same spread in red is a wider interval than in blue
  // relative to a white mean.
  PixelConvergence red, blue;
  for (int i = 0; i < 32; ++i) {
    red.add(glm::vec3(i % 2 ? 2.0f : 0.0f, 1.0f, 1.0f));
    blue.add(glm::vec3(1.0f, 1.0f, i % 2 ? 2.0f : 0.0f));
  }
  // Both means are 1 (in illuminance); the spreads are 0.2126 and 0.0722 of the zero-to-two one.
  EXPECT_FALSE(red.converged(0.35203 * 0.2126 * 0.99));
  EXPECT_TRUE(red.converged(0.35203 * 0.2126 * 1.01));
  EXPECT_FALSE(blue.converged(0.35203 * 0.0722 * 0.99));
  EXPECT_TRUE(blue.converged(0.35203 * 0.0722 * 1.01));
}

TEST(Render, AdaptiveSamplingSpendsSamplesWhereTheNoiseIsAndIsTheSameAtAnyThreadCount) {
  Scene scene = load_scene(source_path("scenes/cornell.json"));
  scene.camera.width = 24;
  scene.camera.height = 24;
  RenderSettings settings;
  settings.integrator = IntegratorKind::Path;
  settings.max_depth = scene.max_depth;
  settings.samples_per_pixel = 256;
  settings.adaptive_tolerance = 0.05f;
  settings.threads = 2;
  const RenderOutput two = render_with_variance(scene, settings);
  settings.threads = 1;
  const RenderOutput one = render_with_variance(scene, settings);
  EXPECT_EQ(one.mean.pixels(), two.mean.pixels()) << "adaptive: 1 and 2 threads differ";
  EXPECT_EQ(one.sample_rate.pixels(), two.sample_rate.pixels()) << "adaptive: 1 and 2 threads took other samples";

  // Pixels stop after a whole number of batches of 32: the brightly lit ones early, the dim,
  // noisy corners after all 256.
  int at_first_batch = 0, at_most = 0, between = 0;
  for (const glm::vec3& rate : one.sample_rate.pixels()) {
    const float samples = rate.x * 256.0f;
    EXPECT_EQ(rate.x, rate.y);
    EXPECT_EQ(std::fmod(samples, 32.0f), 0.0f) << samples << " samples: not a whole number of batches";
    if (samples == 32.0f) ++at_first_batch;
    else if (samples == 256.0f) ++at_most;
    else ++between;
  }
  EXPECT_GT(at_first_batch + between, 24 * 24 / 20) << "few pixels stopped early";
  EXPECT_GT(at_most, 0) << "no pixel took all its samples";

  // The same picture as without adaptive sampling, within the noise: the image's mean
  // illuminance within 2%.
  settings.adaptive_tolerance = 0.0f;
  const Image full = render(scene, settings);
  EXPECT_TRUE(full.width() == 24 && one.sample_rate.width() == 24);
  auto mean_illuminance = [](const Image& image) {
    double sum = 0.0;
    for (const glm::vec3& p : image.pixels()) sum += 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
    return sum / static_cast<double>(image.pixels().size());
  };
  EXPECT_NEAR(mean_illuminance(one.mean), mean_illuminance(full), 0.02 * mean_illuminance(full));
  EXPECT_EQ(render_with_variance(scene, settings).sample_rate.width(), 0) << "no sample rate without --adaptive";

  settings.adaptive_tolerance = -0.1f;
  EXPECT_THROW((void)render(scene, settings), std::invalid_argument);
  settings.adaptive_tolerance = 0.05f;
  settings.adaptive_batch = 1;
  EXPECT_THROW((void)render(scene, settings), std::invalid_argument);
}

TEST(Render, RefusesSampleCountsOutsideTheLimits) {
  Scene scene = load_scene(source_path("scenes/whitted.json"));
  RenderSettings settings;
  settings.samples_per_pixel = 0;
  EXPECT_THROW((void)render(scene, settings), std::invalid_argument);
  settings.samples_per_pixel = kMaxSamplesPerPixel + 1;
  EXPECT_THROW((void)render(scene, settings), std::invalid_argument);
}

}  // namespace
}  // namespace raylab
