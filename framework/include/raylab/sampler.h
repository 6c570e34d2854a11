// The sampler: the random numbers of one pixel sample, as a pure function of (pixel, sample
// index, dimension) and the render's seed. No state is shared between pixels or threads, so
// an image is bit-identical at any thread count and on every run.
//
// Use (per pixel sample, in this order):
//   sampler.start_pixel_sample(pixel_x, pixel_y, sample_index);   // dimension 0
//   glm::vec2 position_in_pixel = sampler.get_pixel_2d();          // the camera ray's point
//   float u = sampler.get_1d(); glm::vec2 uv = sampler.get_2d();   // then as the integrator needs
// Each call takes the next dimension; the same call sequence gives the same numbers.
//
// Stratified and progressive: every dimension (a 1D value or a 2D pair) of a pixel's samples is
// an Owen-scrambled Sobol' sequence (Burley, "Practical Hash-based Owen Scrambling", JCGT 2020),
// padded: each dimension has its own scrambling and its own shuffle of the sample index, drawn
// from a hash of (pixel, dimension, seed), so that dimensions are not correlated with each
// other. The first 2^k samples of a pixel, for every k, put one value in each of the 2^k equal
// intervals of a 1D dimension, and one point in each of the 2^k cells of every grid of
// 2^a x 2^b cells (a + b = k) of a 2D dimension (a (0, k, 2)-net). The sample count does not
// change the numbers (a pixel's first 4 samples are the same at --spp 4 and --spp 64; only
// one sample per pixel is special, the pixel's centre), so a pixel that stops early, as
// adaptive sampling does, keeps samples as well spread as a render of that count. Within its
// cell a value is uniformly random. All values are in [0, 1). docs/07_sampling.md, section 9.
// The numbers of sixteen dimensions are computed at once, when a draw needs one not held (see
// fill_block below); a draw is then a comparison and a read.
#pragma once

#include "raylab/math.h"
#include "raylab/owen_sobol.h"
#include "raylab/random.h"

#include <cstdint>

namespace raylab {

class Sampler {
 public:
  // samples_per_pixel >= 1: how many samples each pixel takes (at 1, get_pixel_2d() is the
  // pixel's centre). seed: changes every number (different seeds give independent renders).
  explicit Sampler(int samples_per_pixel, std::uint64_t seed = 0);

  // A sampler of one sample per pixel that gives the same numbers at every dimension: every
  // get_1d() returns u1 and every get_2d() returns u2 (get_pixel_2d() the pixel's centre). The
  // grader's scripted paths (stage 09b) use it to know which light point and which BSDF direction
  // a path takes, whatever order the code draws them in. u1 and u2's coordinates in [0, 1).
  static Sampler constant(float u1, glm::vec2 u2);

  // Starts sample `sample_index` (0 .. samples_per_pixel - 1) of pixel (pixel_x, pixel_y), at
  // dimension 0.
  void start_pixel_sample(int pixel_x, int pixel_y, int sample_index) {
    if (static_cast<std::uint32_t>(pixel_x) != pixel_x_ || static_cast<std::uint32_t>(pixel_y) != pixel_y_) {
      pixel_x_ = static_cast<std::uint32_t>(pixel_x);
      pixel_y_ = static_cast<std::uint32_t>(pixel_y);
      pixel_key_ready_ = false;  // hashed at the first number drawn: a Whitted render draws none
    }
    reversed_sample_index_ = owen_sobol::reverse_bits(static_cast<std::uint32_t>(sample_index));
    dimension_ = 0;
    block_end_ = 0;  // the numbers held are another sample's
  }

  float get_1d();
  glm::vec2 get_2d();
  // The point in the pixel the camera ray passes through, each coordinate in [0, 1). At one
  // sample per pixel it is the pixel's centre (0.5, 0.5), so that a 1-spp render is exactly
  // the stage-01 picture; with more samples it is a 2D sample like get_2d.
  glm::vec2 get_pixel_2d() {
    if (samples_per_pixel_ == 1) {
      ++dimension_;  // the same dimensions follow at any sample count
      return glm::vec2(0.5f);
    }
    return get_2d();
  }

  int samples_per_pixel() const { return samples_per_pixel_; }
  int dimension() const { return dimension_; }

 private:
  // The numbers of the 16 dimensions 16k, ..., 16k + 15 that contain dimension_, computed
  // together (owen_sobol::fill_dimension_blocks: two blocks of eight dimensions, each in the lanes
  // of AVX2 where the CPU has it; the same numbers either way). A draw then reads them: hashing each
  // dimension on its own was a fifth of a path's instructions (docs/performance.md, "The
  // sampler"). The blocks' seeds depend on the pixel, not on the sample: the first
  // kSeedBlocksHeld blocks' are kept for the pixel's next samples (the same section).
  void fill_block();
  // Block `block`'s seeds for this pixel: kept, or (past those kept) computed into `scratch`.
  const owen_sobol::BlockSeeds& seeds_of_block(std::uint32_t block, owen_sobol::BlockSeeds& scratch);

  static constexpr std::uint32_t kSeedBlocksHeld = 8;  // dimensions 0-63
  static_assert(kSeedBlocksHeld <= 32 && kSeedBlocksHeld % owen_sobol::kBlocksAtOnce == 0,
                "seeds_held_ has a bit per block, and a fill's blocks are all kept or none");

  int samples_per_pixel_ = 1;
  std::uint64_t seed_ = 0;
  std::uint32_t pixel_x_ = 0, pixel_y_ = 0;
  std::uint64_t pixel_key_ = 0;  // owen_sobol::pixel_key, once a number is drawn
  bool pixel_key_ready_ = false;
  std::uint32_t seeds_held_ = 0;  // bit b: seeds_[b] holds block b's seeds for this pixel (with pixel_key_)
  std::uint32_t reversed_sample_index_ = 0;  // the sample index, its bits reversed
  int dimension_ = 0;
  int block_start_ = 0, block_end_ = 0;  // the dimensions [block_start_, block_end_) held below
  float block_first_[owen_sobol::kDimensionsAtOnce] = {};   // each one's 1D number (and 2D x)
  float block_second_[owen_sobol::kDimensionsAtOnce] = {};  // each one's 2D y
  owen_sobol::BlockSeeds seeds_[kSeedBlocksHeld] = {};  // read only where seeds_held_ says
  // The seeds of blocks 8 and up (dimension 64 on), computed again at every fill.
  owen_sobol::BlockSeeds extra_seeds_[owen_sobol::kBlocksAtOnce] = {};
  bool constant_ = false;  // Sampler::constant: the numbers below at every dimension
  float constant_1d_ = 0.0f;
  glm::vec2 constant_2d_{0.0f};
};

// The draws, inline: a comparison and a read; the numbers filled every kDimensionsAtOnce dimensions.
inline float Sampler::get_1d() {
  if (dimension_ >= block_end_) {
    if (constant_) {
      ++dimension_;
      return constant_1d_;
    }
    fill_block();
  }
  return block_first_[dimension_++ - block_start_];
}

inline glm::vec2 Sampler::get_2d() {
  if (dimension_ >= block_end_) {
    if (constant_) {
      ++dimension_;
      return constant_2d_;
    }
    fill_block();
  }
  const int at = dimension_++ - block_start_;
  return {block_first_[at], block_second_[at]};
}

}  // namespace raylab
