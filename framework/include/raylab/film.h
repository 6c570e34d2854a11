// The film: accumulates the samples of every pixel and gives their mean (the image) and, when
// asked for, the variance of that mean per pixel (how far the image may be from its
// expectation: the grader's tests through the noise, and adaptive sampling, read it).
//
// The renderer keeps one film per tile (render.cpp; with --spp-by-noise one for the whole image,
// kept between its two passes): each pixel is written by one thread, in sample order, so the
// result is the same at any thread count, and the memory beyond the image is one tile's (the
// whole image's again with --spp-by-noise). Sums are kept in double: a mean of many
// float samples loses nothing, and a mean of one sample is that sample exactly.
#pragma once

#include "raylab/image.h"
#include "raylab/math.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace raylab {

class Film {
 public:
  Film(int width, int height, bool track_variance);

  int width() const { return width_; }
  int height() const { return height_; }
  bool tracks_variance() const { return track_variance_; }

  void add_sample(int x, int y, const glm::vec3& value) {
    const std::size_t i = index(x, y);
    const glm::dvec3 sample(value);
    const std::uint32_t count = ++counts_[i];
    if (track_variance_) {
      // Welford's update of the mean and the squared deviations: stable for many samples.
      const glm::dvec3 mean_before = count > 1u ? sums_[i] / static_cast<double>(count - 1u) : glm::dvec3(0.0);
      const glm::dvec3 mean_after = mean_before + (sample - mean_before) / static_cast<double>(count);
      squared_error_[i] += (sample - mean_before) * (sample - mean_after);
    }
    sums_[i] += sample;
  }

  std::uint32_t sample_count(int x, int y) const { return counts_[index(x, y)]; }
  // The mean of pixel (x, y)'s samples (black if it has none).
  glm::vec3 mean_at(int x, int y) const {
    const std::size_t i = index(x, y);
    if (counts_[i] == 1u) return glm::vec3(sums_[i]);  // the one sample, exactly
    return counts_[i] > 1u ? glm::vec3(sums_[i] / static_cast<double>(counts_[i])) : glm::vec3(0.0f);
  }
  // See variance_of_mean(); requires tracks_variance().
  glm::vec3 variance_of_mean_at(int x, int y) const;
  // The mean of each pixel's samples (black where there are none).
  Image mean() const;
  // Per pixel and channel: the sample variance s^2 (with n - 1) divided by n, the estimated
  // variance of the pixel's mean; 0 where a pixel has fewer than 2 samples. Only when the film
  // tracks variance (throws std::logic_error otherwise).
  Image variance_of_mean() const;

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x); }

  int width_ = 0, height_ = 0;
  bool track_variance_ = false;
  std::vector<std::uint32_t> counts_;
  std::vector<glm::dvec3> sums_;           // the sum of each pixel's samples
  std::vector<glm::dvec3> squared_error_;  // sum of squared deviations from the mean (Welford's M2)
};

// Adaptive sampling (CS184's rule, docs/09_path.md, section 7): a pixel has samples enough
// when the 95% confidence interval of its mean illuminance lies within `tolerance` of that mean,
//   1.96 sigma / sqrt(n) <= tolerance * mean,
// with sigma the samples' standard deviation (divided by n - 1) and the illuminance of a
// sample 0.2126 R + 0.7152 G + 0.0722 B. The renderer asks after every batch of samples.
// One change from CS184: a pixel whose samples are all 0 so far (mean and spread 0, which the
// rule takes as known) is not done. In a dim corner most paths find no light, and a first
// batch of only zeros would leave a black pixel where the picture is not black.
class PixelConvergence {
 public:
  void add(const glm::vec3& sample) {
    const double illuminance = 0.2126 * sample.x + 0.7152 * sample.y + 0.0722 * sample.z;
    sum_ += illuminance;
    sum_of_squares_ += illuminance * illuminance;
    ++count_;
  }
  std::uint32_t count() const { return count_; }
  // False with fewer than 2 samples, while they are all 0, or while a sample is NaN or infinite.
  bool converged(double tolerance) const {
    if (count_ < 2u) return false;
    const double n = static_cast<double>(count_);
    const double mean = sum_ / n;
    if (!(mean > 0.0)) return false;
    // s^2 = (sum x^2 - n mean^2) / (n - 1), never below 0 (rounding).
    const double variance = std::max(0.0, (sum_of_squares_ - sum_ * mean) / (n - 1.0));
    return 1.96 * std::sqrt(variance / n) <= tolerance * mean;
  }

 private:
  double sum_ = 0.0, sum_of_squares_ = 0.0;
  std::uint32_t count_ = 0;
};

}  // namespace raylab
