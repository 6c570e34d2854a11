#include "raylab/sampler.h"

#include "raylab/avx2.h"

#include <stdexcept>
#include <string>

namespace raylab {

Sampler::Sampler(int samples_per_pixel, std::uint64_t seed) : samples_per_pixel_(samples_per_pixel), seed_(seed) {
  if (samples_per_pixel < 1)
    throw std::invalid_argument("samples per pixel must be at least 1, got " + std::to_string(samples_per_pixel));
}

Sampler Sampler::constant(float u1, glm::vec2 u2) {
  for (const float u : {u1, u2.x, u2.y})
    if (!(u >= 0.0f && u < 1.0f))
      throw std::invalid_argument("a constant sampler's numbers must be in [0, 1), got " + std::to_string(u));
  Sampler sampler(1);
  sampler.constant_ = true;
  sampler.constant_1d_ = u1;
  sampler.constant_2d_ = u2;
  return sampler;
}

void Sampler::fill_block() {
  if (!pixel_key_ready_) {
    pixel_key_ = owen_sobol::pixel_key(pixel_x_, pixel_y_, seed_);
    pixel_key_ready_ = true;
    seeds_held_ = 0;
  }
  // Blocks 2k and 2k + 1, the pair that contains dimension_: every sample of a pixel fills the same
  // blocks, so they share the blocks' seeds.
  const auto low_block =
      static_cast<std::uint32_t>(dimension_) / owen_sobol::kDimensionsAtOnce * owen_sobol::kBlocksAtOnce;
  owen_sobol::fill_dimension_blocks(seeds_of_block(low_block, extra_seeds_[0]),
                                    seeds_of_block(low_block + 1, extra_seeds_[1]), reversed_sample_index_,
                                    block_first_, block_second_);
  block_start_ = static_cast<int>(low_block * owen_sobol::kBlockDimensions);
  block_end_ = block_start_ + owen_sobol::kDimensionsAtOnce;
}

const owen_sobol::BlockSeeds& Sampler::seeds_of_block(std::uint32_t block, owen_sobol::BlockSeeds& scratch) {
  const std::uint32_t first_dimension = block * owen_sobol::kBlockDimensions;
  if (block >= kSeedBlocksHeld) {
    owen_sobol::block_seeds(pixel_key_, first_dimension, scratch);
    return scratch;
  }
  if (!(seeds_held_ & (1u << block))) {
    owen_sobol::block_seeds(pixel_key_, first_dimension, seeds_[block]);
    seeds_held_ |= 1u << block;
  }
  return seeds_[block];
}

namespace owen_sobol {

void block_seeds_one_by_one(std::uint64_t pixel_key, std::uint32_t first_dimension, BlockSeeds& seeds) {
  for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(kBlockDimensions); ++i) {
    const DimensionSeeds dimension(dimension_key(pixel_key, first_dimension + i));
    seeds.shuffle[i] = dimension.shuffle;
    seeds.first[i] = dimension.first;
    seeds.second[i] = dimension.second;
  }
}

void fill_dimension_blocks_one_by_one(const BlockSeeds& low, const BlockSeeds& high,
                                      std::uint32_t reversed_sample_index, float first[kDimensionsAtOnce],
                                      float second[kDimensionsAtOnce]) {
  for (int i = 0; i < kDimensionsAtOnce; ++i) {
    const BlockSeeds& seeds = i < kBlockDimensions ? low : high;
    const int lane = i % kBlockDimensions;
    dimension_numbers(DimensionSeeds(seeds.shuffle[lane], seeds.first[lane], seeds.second[lane]),
                      reversed_sample_index, first[i], second[i]);
  }
}

#if RAYLAB_AVX2_COMPILES
namespace {

// The low 64 bits of a * b in each 64-bit lane (AVX2 multiplies 32 by 32 bits): lo*lo + (hi*lo + lo*hi) << 32.
__attribute__((target("avx2"))) inline __m256i multiply_64(__m256i a, std::uint64_t b) {
  const __m256i b_low = _mm256_set1_epi64x(static_cast<long long>(b & 0xffffffffu));
  const __m256i b_high = _mm256_set1_epi64x(static_cast<long long>(b >> 32u));
  const __m256i cross = _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(a, 32), b_low), _mm256_mul_epu32(a, b_high));
  return _mm256_add_epi64(_mm256_mul_epu32(a, b_low), _mm256_slli_epi64(cross, 32));
}

// mix_bits (raylab/random.h) in four 64-bit lanes.
__attribute__((target("avx2"))) inline __m256i mix_bits_4(__m256i value) {
  value = multiply_64(_mm256_xor_si256(value, _mm256_srli_epi64(value, 30)), 0xbf58476d1ce4e5b9ULL);
  value = multiply_64(_mm256_xor_si256(value, _mm256_srli_epi64(value, 27)), 0x94d049bb133111ebULL);
  return _mm256_xor_si256(value, _mm256_srli_epi64(value, 31));
}

// The low (or high) 32 bits of the 64-bit lanes of a (lanes 0-3) and b (lanes 4-7), in eight lanes.
__attribute__((target("avx2"))) inline __m256i halves_8(__m256i a, __m256i b, bool high) {
  const __m256 mixed = high ? _mm256_shuffle_ps(_mm256_castsi256_ps(a), _mm256_castsi256_ps(b), _MM_SHUFFLE(3, 1, 3, 1))
                            : _mm256_shuffle_ps(_mm256_castsi256_ps(a), _mm256_castsi256_ps(b), _MM_SHUFFLE(2, 0, 2, 0));
  // (a0 a1 b0 b1 | a2 a3 b2 b3) -> (a0 a1 a2 a3 | b0 b1 b2 b3)
  return _mm256_permute4x64_epi64(_mm256_castps_si256(mixed), _MM_SHUFFLE(3, 1, 2, 0));
}

// laine_karras_permutation in eight lanes.
__attribute__((target("avx2"))) inline __m256i laine_karras_8(__m256i x, __m256i seed) {
  x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(0x3d20adea)));
  x = _mm256_add_epi32(x, seed);
  x = _mm256_mullo_epi32(x, _mm256_or_si256(_mm256_srli_epi32(seed, 16), _mm256_set1_epi32(1)));
  x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(0x05526c56)));
  x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(0x53a22864)));
  return x;
}

// reverse_bits in eight lanes: the bytes swapped, then each byte's bits by two table lookups of
// its nibbles.
__attribute__((target("avx2"))) inline __m256i reverse_bits_8(__m256i x) {
  const __m256i swap_bytes = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12,  //
                                              3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
  // A nibble n's four bits in the opposite order, in the high nibble of a byte (for the byte's low
  // nibble) or the low one (for its high nibble).
  alignas(16) static const std::uint8_t kReversedHigh[16] = {0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0,
                                                              0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0};
  alignas(16) static const std::uint8_t kReversedLow[16] = {0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe,
                                                             0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf};
  const __m256i reversed_high = _mm256_broadcastsi128_si256(_mm_load_si128(reinterpret_cast<const __m128i*>(kReversedHigh)));
  const __m256i reversed_low = _mm256_broadcastsi128_si256(_mm_load_si128(reinterpret_cast<const __m128i*>(kReversedLow)));
  const __m256i nibble = _mm256_set1_epi8(0x0f);
  x = _mm256_shuffle_epi8(x, swap_bytes);
  const __m256i low = _mm256_and_si256(x, nibble);
  const __m256i high = _mm256_and_si256(_mm256_srli_epi16(x, 4), nibble);
  return _mm256_or_si256(_mm256_shuffle_epi8(reversed_high, low), _mm256_shuffle_epi8(reversed_low, high));
}

// A block's column of seeds, in eight lanes.
__attribute__((target("avx2"))) inline __m256i load(const std::uint32_t column[kBlockDimensions]) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(column));
}

// to_unit_float in eight lanes, stored.
__attribute__((target("avx2"))) inline void store_unit_floats_8(float* out, __m256i fraction) {
  const __m256 value = _mm256_cvtepi32_ps(_mm256_srli_epi32(fraction, 8));  // below 2^24: exact
  _mm256_storeu_ps(out, _mm256_mul_ps(value, _mm256_set1_ps(0x1p-24f)));
}

}  // namespace

__attribute__((target("avx2"))) static void block_seeds_avx2_lanes(std::uint64_t pixel_key,
                                                                   std::uint32_t first_dimension, BlockSeeds& seeds) {
  // The keys (dimension_key), dimensions 0-3 and 4-7 of the block.
  const auto lane = [&](std::uint32_t k) {
    return static_cast<long long>(dimension_key_unmixed(pixel_key, first_dimension + k));
  };
  const __m256i key_a = mix_bits_4(_mm256_setr_epi64x(lane(0), lane(1), lane(2), lane(3)));
  const __m256i key_b = mix_bits_4(_mm256_setr_epi64x(lane(4), lane(5), lane(6), lane(7)));
  // DimensionSeeds: shuffle the key's low half, first its high half, second the high half of key * constant.
  constexpr std::uint64_t kSecond = 0xd1342543de82ef95ULL;
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(seeds.shuffle), halves_8(key_a, key_b, false));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(seeds.first), halves_8(key_a, key_b, true));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(seeds.second),
                     halves_8(multiply_64(key_a, kSecond), multiply_64(key_b, kSecond), true));
}

// One block's numbers (dimension_numbers in eight lanes), inlined twice in fill_blocks_avx2.
__attribute__((target("avx2"), always_inline)) static inline void fill_block_avx2(const BlockSeeds& seeds,
                                                                           std::uint32_t reversed_sample_index,
                                                                           float first[], float second[]) {
  // owen_scramble_reversed of the reversed sample index: the shuffled index.
  const __m256i index = reverse_bits_8(
      laine_karras_8(_mm256_set1_epi32(static_cast<int>(reversed_sample_index)), load(seeds.shuffle)));
  store_unit_floats_8(first, reverse_bits_8(laine_karras_8(index, load(seeds.first))));
  // kSobolSecondDimension.of(index): its four tables, one per byte, gathered.
  const auto table = [](int byte) { return reinterpret_cast<const int*>(kSobolSecondDimension.reversed[byte]); };
  const __m256i low_byte = _mm256_set1_epi32(0xff);
  __m256i sobol = _mm256_i32gather_epi32(table(0), _mm256_and_si256(index, low_byte), 4);
  sobol = _mm256_xor_si256(
      sobol, _mm256_i32gather_epi32(table(1), _mm256_and_si256(_mm256_srli_epi32(index, 8), low_byte), 4));
  sobol = _mm256_xor_si256(
      sobol, _mm256_i32gather_epi32(table(2), _mm256_and_si256(_mm256_srli_epi32(index, 16), low_byte), 4));
  sobol = _mm256_xor_si256(sobol, _mm256_i32gather_epi32(table(3), _mm256_srli_epi32(index, 24), 4));
  store_unit_floats_8(second, reverse_bits_8(laine_karras_8(sobol, load(seeds.second))));
}

// Two blocks' numbers: two independent chains in one function, which the processor runs side by side.
__attribute__((target("avx2"))) static void fill_blocks_avx2(const BlockSeeds& low, const BlockSeeds& high,
                                                             std::uint32_t reversed_sample_index, float first[],
                                                             float second[]) {
  fill_block_avx2(low, reversed_sample_index, first, second);
  fill_block_avx2(high, reversed_sample_index, first + kBlockDimensions, second + kBlockDimensions);
}
#endif

bool block_seeds_avx2(std::uint64_t pixel_key, std::uint32_t first_dimension, BlockSeeds& seeds) {
#if RAYLAB_AVX2_COMPILES
  if (!avx2_runs_here()) return false;
  block_seeds_avx2_lanes(pixel_key, first_dimension, seeds);
  return true;
#else
  (void)pixel_key, (void)first_dimension, (void)seeds;
  return false;
#endif
}

bool fill_dimension_blocks_avx2(const BlockSeeds& low, const BlockSeeds& high, std::uint32_t reversed_sample_index,
                                float first[kDimensionsAtOnce], float second[kDimensionsAtOnce]) {
#if RAYLAB_AVX2_COMPILES
  if (!avx2_runs_here()) return false;
  fill_blocks_avx2(low, high, reversed_sample_index, first, second);
  return true;
#else
  (void)low, (void)high, (void)reversed_sample_index, (void)first, (void)second;
  return false;
#endif
}

namespace {
// The ways this CPU takes, chosen once.
using BlockSeedsWay = void (*)(std::uint64_t, std::uint32_t, BlockSeeds&);
using FillBlocksWay = void (*)(const BlockSeeds&, const BlockSeeds&, std::uint32_t, float[], float[]);
BlockSeedsWay chosen_block_seeds() {
#if RAYLAB_AVX2_COMPILES
  if (avx2_runs_here()) return &block_seeds_avx2_lanes;
#endif
  return &block_seeds_one_by_one;
}
FillBlocksWay chosen_fill_blocks() {
#if RAYLAB_AVX2_COMPILES
  if (avx2_runs_here()) return &fill_blocks_avx2;
#endif
  return &fill_dimension_blocks_one_by_one;
}
}  // namespace

void block_seeds(std::uint64_t pixel_key, std::uint32_t first_dimension, BlockSeeds& seeds) {
  static const BlockSeedsWay way = chosen_block_seeds();
  way(pixel_key, first_dimension, seeds);
}

void fill_dimension_blocks(const BlockSeeds& low, const BlockSeeds& high, std::uint32_t reversed_sample_index,
                           float first[kDimensionsAtOnce], float second[kDimensionsAtOnce]) {
  static const FillBlocksWay way = chosen_fill_blocks();
  way(low, high, reversed_sample_index, first, second);
}

}  // namespace owen_sobol
}  // namespace raylab
