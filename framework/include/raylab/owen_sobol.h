// The arithmetic of the sampler's points (sampler.h): Owen-scrambled Sobol' numbers by Burley's
// hash ("Practical Hash-based Owen Scrambling", JCGT 2020): dimension_numbers below defines a
// dimension's numbers, and fill_dimension_blocks computes sixteen dimensions' at once for the sampler
// (sampler.cpp); docs/07_sampling.md, section 9, explains them.
#pragma once

#include "raylab/random.h"

#include <cstdint>

namespace raylab::owen_sobol {

// The bits of x in the opposite order: bit 0 becomes bit 31.
constexpr std::uint32_t reverse_bits(std::uint32_t x) {
  x = (x << 16u) | (x >> 16u);
  x = ((x & 0x00ff00ffu) << 8u) | ((x >> 8u) & 0x00ff00ffu);
  x = ((x & 0x0f0f0f0fu) << 4u) | ((x >> 4u) & 0x0f0f0f0fu);
  x = ((x & 0x33333333u) << 2u) | ((x >> 2u) & 0x33333333u);
  x = ((x & 0x55555555u) << 1u) | ((x >> 1u) & 0x55555555u);
  return x;
}

// A permutation of the 32-bit numbers, chosen by `seed`, in which every output bit depends only on
// the input bits at and below it (Laine and Karras 2011): multiplying by an even number or adding
// only carries upwards, and each step can be undone. Burley's hash, with the constants Vegdahl
// (2021) found to scramble better.
constexpr std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16u) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

// Owen scrambling of a number read as a binary fraction (bit 31 is the 1/2 digit): every digit is
// flipped or not at random, depending on the digits before it. On the reversed bits this is a
// Laine-Karras permutation. For a sample index (bit 0 first) it is the shuffle of a pixel's
// samples that keeps every block of 2^k consecutive indices whole.
constexpr std::uint32_t owen_scramble_reversed(std::uint32_t reversed_value, std::uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reversed_value, seed));
}

// The second dimension of Sobol's sequence, with its bits reversed, as four tables of 256 (one per
// byte of the index): the sequence is linear in the index's bits (XOR), so the tables' entries for
// the index's four bytes XOR together. Its direction numbers are v_0 = 2^31, v_k = v_(k-1) XOR
// (v_(k-1) >> 1). (The first dimension is the index's bits reversed: the van der Corput sequence.)
struct SobolSecondDimension {
  std::uint32_t reversed[4][256] = {};
  constexpr SobolSecondDimension() {
    std::uint32_t direction_reversed[32] = {};
    std::uint32_t direction = 1u << 31u;
    for (int k = 0; k < 32; ++k) {
      direction_reversed[k] = reverse_bits(direction);
      direction ^= direction >> 1u;
    }
    // Each table by its highest bit: value = (value - 2^bit) + 2^bit. About a thousand steps, well
    // within every compiler's budget for constant evaluation (MSVC's is 100 000 by default).
    for (int byte = 0; byte < 4; ++byte)
      for (int bit = 0; bit < 8; ++bit)
        for (std::uint32_t value = 1u << bit; value < (2u << bit); ++value)
          reversed[byte][value] = reversed[byte][value - (1u << bit)] ^ direction_reversed[8 * byte + bit];
  }
  constexpr std::uint32_t of(std::uint32_t index) const {
    return reversed[0][index & 0xffu] ^ reversed[1][(index >> 8u) & 0xffu] ^ reversed[2][(index >> 16u) & 0xffu] ^
           reversed[3][index >> 24u];
  }
};
inline constexpr SobolSecondDimension kSobolSecondDimension;
// Its direction numbers against known values (Joe and Kuo's dimension 2; bit k of the index is
// v_k, whose bits are row k of Pascal's triangle modulo 2): v_1 = 0xc0000000, v_8 = 0x80800000,
// v_15 = 0xffff0000, v_31 = 0xffffffff, here bit-reversed.
static_assert(kSobolSecondDimension.of(1u << 1u) == reverse_bits(0xc0000000u), "Sobol' v_1");
static_assert(kSobolSecondDimension.of(1u << 8u) == reverse_bits(0x80800000u), "Sobol' v_8");
static_assert(kSobolSecondDimension.of(1u << 15u) == reverse_bits(0xffff0000u), "Sobol' v_15");
static_assert(kSobolSecondDimension.of(1u << 31u) == 0xffffffffu, "Sobol' v_31");
static_assert(kSobolSecondDimension.of(3u) == reverse_bits(0x80000000u ^ 0xc0000000u), "Sobol' linearity");

// The 24 leading bits of a binary fraction as a float in [0, 1), exactly.
inline float to_unit_float(std::uint32_t fraction) { return static_cast<float>(fraction >> 8u) * 0x1p-24f; }

// One dimension's three scramblings from its 64-bit key: the shuffle of the sample index, and the
// Owen scrambling of each coordinate. They depend on the pixel and the dimension, not on the
// sample: the sampler keeps them for a pixel's samples.
struct DimensionSeeds {
  std::uint32_t shuffle, first, second;
  explicit DimensionSeeds(std::uint64_t key)
      : shuffle(static_cast<std::uint32_t>(key)),
        first(static_cast<std::uint32_t>(key >> 32u)),
        second(static_cast<std::uint32_t>((key * 0xd1342543de82ef95ULL) >> 32u)) {}
  DimensionSeeds(std::uint32_t shuffle_seed, std::uint32_t first_seed, std::uint32_t second_seed)
      : shuffle(shuffle_seed), first(first_seed), second(second_seed) {}
};

// The numbers of one dimension of one pixel sample, from the dimension's seeds (of its key,
// dimension_key) and the sample index with its bits reversed: `first`, its 1D number and a 2D
// point's x (the shuffled index's van der Corput value, scrambled), and `second`, the 2D point's y
// (Sobol's second dimension at the same index, scrambled on its own).
inline void dimension_numbers(const DimensionSeeds& seeds, std::uint32_t reversed_sample_index, float& first,
                              float& second) {
  const std::uint32_t index = owen_scramble_reversed(reversed_sample_index, seeds.shuffle);
  first = to_unit_float(owen_scramble_reversed(index, seeds.first));
  second = to_unit_float(owen_scramble_reversed(kSobolSecondDimension.of(index), seeds.second));
}
inline void dimension_numbers(std::uint64_t key, std::uint32_t reversed_sample_index, float& first, float& second) {
  dimension_numbers(DimensionSeeds(key), reversed_sample_index, first, second);
}

// The key of a pixel's samples: its coordinates and the render's seed, hashed.
constexpr std::uint64_t pixel_key(std::uint32_t pixel_x, std::uint32_t pixel_y, std::uint64_t seed) {
  return mix_bits(((static_cast<std::uint64_t>(pixel_y) << 32u) | pixel_x) ^ mix_bits(seed + 0x9e3779b97f4a7c15ULL));
}

// The key of dimension `dimension` of a pixel sample whose pixel has the key pixel_key:
// dimension_key_unmixed hashed (the dimension's number wraps at 2^32).
constexpr std::uint64_t dimension_key_unmixed(std::uint64_t pixel_key, std::uint32_t dimension) {
  return pixel_key + static_cast<std::uint64_t>(dimension) * 0x9e3779b97f4a7c15ULL;
}
constexpr std::uint64_t dimension_key(std::uint64_t pixel_key, std::uint32_t dimension) {
  return mix_bits(dimension_key_unmixed(pixel_key, dimension));
}

// Dimensions go in blocks of eight, the lanes of AVX2.
constexpr int kBlockDimensions = 8;
// The sampler computes two blocks at once: each block's numbers are one long chain of dependent
// steps (the shuffle's Laine-Karras permutation, then the Sobol' table's gathers and the second
// coordinate's permutation, four multiplies each), and two chains side by side take about the
// time of one (docs/performance.md, "The sampler").
constexpr int kBlocksAtOnce = 2;
constexpr int kDimensionsAtOnce = kBlocksAtOnce * kBlockDimensions;

// The seeds (DimensionSeeds) of a block's eight dimensions of a pixel, as columns for the lanes.
struct BlockSeeds {
  std::uint32_t shuffle[kBlockDimensions];
  std::uint32_t first[kBlockDimensions];
  std::uint32_t second[kBlockDimensions];
};

// The seeds of the dimensions first_dimension, first_dimension + 1, ..., + 7 of the pixel whose
// key is pixel_key (DimensionSeeds of dimension_key).
void block_seeds(std::uint64_t pixel_key, std::uint32_t first_dimension, BlockSeeds& seeds);
// dimension_numbers of two blocks' dimensions for one pixel sample: of `low`'s eight into
// first[0 .. 7] and second[0 .. 7], of `high`'s into first[8 .. 15] and second[8 .. 15].
void fill_dimension_blocks(const BlockSeeds& low, const BlockSeeds& high, std::uint32_t reversed_sample_index,
                           float first[kDimensionsAtOnce], float second[kDimensionsAtOnce]);
// Both compute in the lanes of AVX2 where the CPU has it (chosen once, sampler.cpp), else one
// dimension after another: the same numbers, bit for bit, either way. Their two ways, for the
// tests (the AVX2 ones return false, and write nothing, where this compiler or CPU has no AVX2):
void block_seeds_one_by_one(std::uint64_t pixel_key, std::uint32_t first_dimension, BlockSeeds& seeds);
bool block_seeds_avx2(std::uint64_t pixel_key, std::uint32_t first_dimension, BlockSeeds& seeds);
void fill_dimension_blocks_one_by_one(const BlockSeeds& low, const BlockSeeds& high,
                                      std::uint32_t reversed_sample_index, float first[kDimensionsAtOnce],
                                      float second[kDimensionsAtOnce]);
bool fill_dimension_blocks_avx2(const BlockSeeds& low, const BlockSeeds& high, std::uint32_t reversed_sample_index,
                                float first[kDimensionsAtOnce], float second[kDimensionsAtOnce]);

}  // namespace raylab::owen_sobol
