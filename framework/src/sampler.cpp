#include "raylab/sampler.h"

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

}  // namespace raylab
