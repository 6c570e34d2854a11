// Pcg32 against the published reference outputs of O'Neill's pcg_basic (pcg32-demo,
// seed 42, stream 54), and the properties the rest of the kit relies on.
#include "raylab/math.h"
#include "raylab/random.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace raylab {
namespace {

TEST(Pcg32, MatchesTheReferenceImplementationsFirstOutputs) {
  // pcg32_srandom_r(&rng, 42u, 54u) then pcg32_random_r six times (pcg32-demo.c, round 1).
  Pcg32 generator(42u, 54u);
  const std::array<std::uint32_t, 6> expected = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                                 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(generator.next_uint32(), expected[i]) << "output " << i;
}

TEST(Pcg32, SameSeedAndStreamGiveTheSameSequenceOtherStreamsDiffer) {
  Pcg32 first(7u, 3u), again(7u, 3u), other_stream(7u, 4u), other_seed(8u, 3u);
  int differs_stream = 0, differs_seed = 0;
  for (int i = 0; i < 64; ++i) {
    const std::uint32_t value = first.next_uint32();
    EXPECT_EQ(value, again.next_uint32());
    differs_stream += value != other_stream.next_uint32();
    differs_seed += value != other_seed.next_uint32();
  }
  EXPECT_GT(differs_stream, 60);
  EXPECT_GT(differs_seed, 60);
}

TEST(Pcg32, NextFloatIsInTheHalfOpenUnitIntervalOnA24BitGrid) {
  Pcg32 generator;
  for (int i = 0; i < 100000; ++i) {
    const float value = generator.next_float();
    ASSERT_GE(value, 0.0f);
    ASSERT_LT(value, 1.0f);
    const float scaled = value * 16777216.0f;
    ASSERT_EQ(scaled, static_cast<float>(static_cast<std::uint32_t>(scaled)));
  }
}

TEST(Pcg32, UniformStaysBelowHighEvenWhenRoundingWouldReachIt) {
  Pcg32 generator(1u, 2u);
  for (int i = 0; i < 100000; ++i) {
    const float value = generator.uniform(1.0f, 1.0000001f);  // two floats apart
    ASSERT_GE(value, 1.0f);
    ASSERT_LT(value, 1.0000001f);
    const float wide = generator.uniform(-3.0f, 5.0f);
    ASSERT_GE(wide, -3.0f);
    ASSERT_LT(wide, 5.0f);
  }
}

TEST(Pcg32, NextBoundedCoversItsRangeEvenlyAndNeverReachesTheBound) {
  // bound 3 does not divide 2^32, but a plain `% 3` would favour 0 by one part in 2^32,
  // too little to see: the rejection is checked with bound 3 * 2^30, where `%` alone maps
  // the top quarter of the 32-bit values onto [0, 2^30), so that a third of the range would
  // get half of the draws.
  Pcg32 generator(11u, 5u);
  std::vector<int> counts(3, 0);
  const int draws = 30000;
  for (int i = 0; i < draws; ++i) {
    const std::uint32_t value = generator.next_bounded(3u);
    ASSERT_LT(value, 3u);
    ++counts[value];
  }
  for (int count : counts) EXPECT_NEAR(count, draws / 3, 600);  // ~7 sigma

  const std::uint32_t big_bound = 0xc0000000u;  // 3 * 2^30
  int lowest_third = 0;
  for (int i = 0; i < draws; ++i) {
    const std::uint32_t value = generator.next_bounded(big_bound);
    ASSERT_LT(value, big_bound);
    lowest_third += value < 0x40000000u;
  }
  EXPECT_NEAR(lowest_third, draws / 3, 600);  // biased `%`: draws / 2
  EXPECT_EQ(generator.next_bounded(0u), 0u);
  EXPECT_EQ(generator.next_bounded(1u), 0u);
}

TEST(MixBits, IsTheSplitmix64FinaliserAndSpreadsNeighbouringInputs) {
  EXPECT_EQ(mix_bits(0u), 0u);
  // splitmix64's first output from state 0 is mix_bits(0x9e3779b97f4a7c15).
  EXPECT_EQ(mix_bits(0x9e3779b97f4a7c15ULL), 0xe220a8397b1dcdafULL);
  // Neighbouring inputs differ in about half of their 64 output bits.
  for (std::uint64_t input = 1; input < 64; ++input) {
    const std::uint64_t difference = mix_bits(input) ^ mix_bits(input + 1);
    int bits = 0;
    for (int bit = 0; bit < 64; ++bit) bits += static_cast<int>((difference >> bit) & 1u);
    EXPECT_GT(bits, 12) << "inputs " << input << " and " << input + 1;
    EXPECT_LT(bits, 52) << "inputs " << input << " and " << input + 1;
  }
}

// The bits of a float, to compare results bit for bit (-0 against +0, NaN against NaN).
std::uint32_t bits_of(float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

TEST(NextFloat, StepsAsStdNextafterDoesOnEveryKindOfFloat) {
  // The offset of a spawned ray's origin (offset_ray_origin) rounds with these; they must be
  // std::nextafter bit for bit: zeros of both signs, denormals, the largest finite floats,
  // infinities, and ordinary numbers of both signs; NaN stays NaN.
  using limits = std::numeric_limits<float>;
  std::vector<float> values = {0.0f, -0.0f, limits::denorm_min(), -limits::denorm_min(), limits::min(),
                               -limits::min(), limits::max(), -limits::max(), kInfinity, -kInfinity,
                               1.0f, -1.0f, 0x1.fffffep-1f, 278.0f, -800.0f, 1e-30f, -1e-30f};
  Pcg32 random(7, 3);
  for (int i = 0; i < 10000; ++i) {  // any bit pattern: every exponent and sign
    const std::uint32_t bits = random.next_uint32();
    float value;
    std::memcpy(&value, &bits, sizeof value);
    if (!std::isnan(value)) values.push_back(value);
  }
  for (const float value : values) {
    EXPECT_EQ(bits_of(next_float_up(value)), bits_of(std::nextafter(value, kInfinity))) << value;
    EXPECT_EQ(bits_of(next_float_down(value)), bits_of(std::nextafter(value, -kInfinity))) << value;
  }
  EXPECT_TRUE(std::isnan(next_float_up(limits::quiet_NaN())));
  EXPECT_TRUE(std::isnan(next_float_down(limits::quiet_NaN())));
}

}  // namespace
}  // namespace raylab
