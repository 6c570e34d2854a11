#include "raylab/sampler.h"

#include "raylab/random.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace raylab {
namespace {

// A permutation of [0, count), chosen by `key`: a bijection on the smallest power of two
// >= count (odd multiplications and right xorshifts are invertible modulo a power of two),
// walked until the value lands below count (Kensler 2013, section 3).
std::uint32_t permute(std::uint32_t index, std::uint32_t count, std::uint64_t key) {
  if (count <= 1u) return 0u;
  std::uint32_t mask = count - 1u;
  mask |= mask >> 1u; mask |= mask >> 2u; mask |= mask >> 4u; mask |= mask >> 8u; mask |= mask >> 16u;
  const auto key_low = static_cast<std::uint32_t>(key);
  const auto key_high = static_cast<std::uint32_t>(key >> 32u);
  do {
    index ^= key_low;
    index *= 0x9e3779b1u;
    index ^= (index & mask) >> 3u;
    index += key_high;
    index *= 0x85ebca6bu | 1u;
    index ^= (index & mask) >> 5u;
    index *= 0xc2b2ae35u | 1u;
    index ^= (index & mask) >> 2u;
    index &= mask;
  } while (index >= count);
  return index;
}

// A uniform jitter in [0, 1) for (key, sample): the first number of a Pcg32 stream.
float jitter(std::uint64_t key, std::uint32_t sample_index) {
  return Pcg32(key, sample_index).next_float();
}

}  // namespace

Sampler::Sampler(int samples_per_pixel, std::uint64_t seed) : samples_per_pixel_(samples_per_pixel), seed_(seed) {
  if (samples_per_pixel < 1)
    throw std::invalid_argument("samples per pixel must be at least 1, got " + std::to_string(samples_per_pixel));
  grid_columns_ = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(samples_per_pixel)))));
  grid_rows_ = (samples_per_pixel + grid_columns_ - 1) / grid_columns_;
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

std::uint64_t Sampler::dimension_key() {
  if (!pixel_key_ready_) {
    pixel_key_ = mix_bits(pixel_ ^ mix_bits(seed_ + 0x9e3779b97f4a7c15ULL));
    pixel_key_ready_ = true;
  }
  return mix_bits(pixel_key_ + static_cast<std::uint64_t>(dimension_++) * 0x9e3779b97f4a7c15ULL);
}

float Sampler::get_1d() {
  if (constant_) {
    ++dimension_;
    return constant_1d_;
  }
  const std::uint64_t key = dimension_key();
  const auto count = static_cast<std::uint32_t>(samples_per_pixel_);
  const std::uint32_t stratum = permute(sample_index_ % count, count, key);
  const float value = (static_cast<float>(stratum) + jitter(key, sample_index_)) / static_cast<float>(count);
  return std::min(value, 0x1.fffffep-1f);  // the division may round up to 1
}

glm::vec2 Sampler::get_2d() {
  if (constant_) {
    ++dimension_;
    return constant_2d_;
  }
  // Correlated multi-jitter: sample s sits in column s % m, row s / m of the m x n grid; its
  // offset inside the cell is itself a stratum of the cell's finer n x m grid, shuffled per
  // column and row, so that the x and y projections are stratified into m n intervals each.
  const std::uint64_t key = dimension_key();
  const auto m = static_cast<std::uint32_t>(grid_columns_), n = static_cast<std::uint32_t>(grid_rows_);
  const std::uint32_t s = permute(sample_index_ % static_cast<std::uint32_t>(samples_per_pixel_),
                                  static_cast<std::uint32_t>(samples_per_pixel_), key);
  const std::uint32_t column = s % m, row = s / m;
  const std::uint32_t fine_x = permute(row, n, mix_bits(key ^ 0x1u));     // by row: x strata differ
  const std::uint32_t fine_y = permute(column, m, mix_bits(key ^ 0x2u));  // by column: y strata differ
  const float jitter_x = jitter(key ^ 0x3u, sample_index_), jitter_y = jitter(key ^ 0x4u, sample_index_);
  const float x = (static_cast<float>(column) + (static_cast<float>(fine_x) + jitter_x) / static_cast<float>(n)) /
                  static_cast<float>(m);
  const float y = (static_cast<float>(row) + (static_cast<float>(fine_y) + jitter_y) / static_cast<float>(m)) /
                  static_cast<float>(n);
  return {std::min(x, 0x1.fffffep-1f), std::min(y, 0x1.fffffep-1f)};
}

}  // namespace raylab
