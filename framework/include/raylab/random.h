// The kit's one random number generator: PCG32 (M. E. O'Neill, "PCG: A Family of Simple Fast
// Space-Efficient Statistically Good Algorithms for Random Number Generation", 2014), the
// XSH RR variant: 64 bits of state, a 64-bit stream selector, 32 bits out per step. Small,
// fast, well tested, and the same on every compiler and platform (std::mt19937 is too, but
// std::uniform_real_distribution is not). Everything that needs random numbers - the
// autograder's cases, the stress suite, the benchmarks, the mesh generator - draws them from
// here, seeded from what it is computing (mix_bits), never from the clock or a shared stream, so
// every run gives the same numbers. The renderer's sampler (sampler.h) keys its scrambled points
// with mix_bits in the same way.
#pragma once

#include <cmath>
#include <cstdint>

namespace raylab {

class Pcg32 {
 public:
  // PCG's own default seed and stream (pcg_basic's PCG32_INITIALIZER). Two generators with
  // different streams give independent sequences even from the same seed.
  explicit Pcg32(std::uint64_t seed = 0x853c49e6748fea9bULL,
                 std::uint64_t stream = 0xda3e39cb94b95bdbULL) {
    state_ = 0u;
    increment_ = (stream << 1u) | 1u;  // the increment must be odd
    next_uint32();
    state_ += seed;
    next_uint32();
  }

  // Uniform over all 2^32 values.
  std::uint32_t next_uint32() {
    const std::uint64_t old_state = state_;
    state_ = old_state * kMultiplier + increment_;
    const auto xor_shifted = static_cast<std::uint32_t>(((old_state >> 18u) ^ old_state) >> 27u);
    const auto rotation = static_cast<std::uint32_t>(old_state >> 59u);
    return (xor_shifted >> rotation) | (xor_shifted << ((32u - rotation) & 31u));
  }

  // Uniform over [0, bound), without the bias of a plain `% bound`: values below
  // 2^32 mod bound are drawn again. bound 0 (an empty range) returns 0.
  std::uint32_t next_bounded(std::uint32_t bound) {
    if (bound == 0u) return 0u;
    const std::uint32_t threshold = (0u - bound) % bound;  // = 2^32 mod bound
    for (;;) {
      const std::uint32_t value = next_uint32();
      if (value >= threshold) return value % bound;
    }
  }

  // Uniform over [0, 1) with 24 random bits: every value is a multiple of 2^-24, so it is
  // exact in a float and never rounds up to 1.
  float next_float() {
    return static_cast<float>(next_uint32() >> 8u) * (1.0f / 16777216.0f);
  }

  // Uniform over [low, high) for low < high. (low + (high - low) u can round up to high;
  // that one value is moved to the largest float below high.)
  float uniform(float low, float high) {
    const float value = low + (high - low) * next_float();
    return value < high ? value : std::nextafter(high, low);
  }

 private:
  static constexpr std::uint64_t kMultiplier = 6364136223846793005ULL;
  std::uint64_t state_;
  std::uint64_t increment_;
};

// A splitmix64-style finaliser (Steele, Lea and Flood, "Fast splittable pseudorandom number
// generators", 2014): every input bit changes about half of the output bits. Use it to turn
// structured values - a pixel index, a sample index, a case number - into a seed:
// Pcg32(mix_bits(pixel_index), mix_bits(sample_index ^ salt)). mix_bits(0) is 0.
constexpr std::uint64_t mix_bits(std::uint64_t value) {
  value = (value ^ (value >> 30u)) * 0xbf58476d1ce4e5b9ULL;
  value = (value ^ (value >> 27u)) * 0x94d049bb133111ebULL;
  return value ^ (value >> 31u);
}

}  // namespace raylab
