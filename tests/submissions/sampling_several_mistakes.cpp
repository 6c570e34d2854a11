// Grader self-test submission (stage 07_sampling): six mistakes at once, one per function, each named:
// the concentric disk map without its zero check (0 / 0 = NaN at the centre), the disk's pdf with
// the Jacobian r, the sphere with theta uniform (crowding the poles), the triangle's pdf returning
// the area, cosine samples uniform over the hemisphere, the uniform hemisphere's pdf cosine-weighted.
#include "raylab/stages/07_sampling.h"

#include "raylab/math.h"

#include <algorithm>
#include <cmath>

namespace raylab {

glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random) {
  // z = cos(theta) is uniform in [0, 1] (Archimedes: equal heights, equal areas).
  const float z = 1.0f - uniform_random.x;  // in (0, 1]
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * uniform_random.y;
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

float uniform_hemisphere_pdf(const glm::vec3& direction) { return direction.z >= 0.0f ? direction.z / kPi : 0.0f; }

glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random) {
  const float z = uniform_random.x;  // the mistake: z uniform is the uniform hemisphere
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * uniform_random.y;
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

float cosine_hemisphere_pdf(const glm::vec3& direction) { return direction.z > 0.0f ? direction.z / kPi : 0.0f; }

glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random) {
  const float z = std::cos(kPi * uniform_random.x);  // the mistake: theta uniform
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * uniform_random.y;
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

float uniform_sphere_pdf(const glm::vec3& direction) {
  (void)direction;  // the same for every direction
  return 1.0f / (4.0f * kPi);
}

glm::vec2 sample_uniform_disk(glm::vec2 uniform_random) {
  // Shirley and Chiu's concentric map: squares around the centre go to rings, so strata of
  // the unit square stay compact on the disk.
  const glm::vec2 offset = 2.0f * uniform_random - glm::vec2(1.0f);  // [-1, 1)^2
  float radius, angle;
  if (std::fabs(offset.x) > std::fabs(offset.y)) {
    radius = offset.x;
    angle = (kPi / 4.0f) * (offset.y / offset.x);
  } else {
    radius = offset.y;
    angle = kPi / 2.0f - (kPi / 4.0f) * (offset.x / offset.y);
  }
  return radius * glm::vec2(std::cos(angle), std::sin(angle));
}

float uniform_disk_pdf(glm::vec2 point) { return glm::length(point) / kPi; }

Barycentrics sample_uniform_triangle(glm::vec2 uniform_random) {
  // The square-root warp (pbrt-v4, section A.5.5): sqrt(u.x) is the distance from p0 towards
  // the opposite edge (area grows with its square), u.y the position along that edge.
  const float root = std::sqrt(uniform_random.x);
  return Barycentrics{root * (1.0f - uniform_random.y), root * uniform_random.y};
}

float uniform_triangle_pdf(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  const float twice_area = glm::length(glm::cross(p1 - p0, p2 - p0));
  return 0.5f * twice_area;  // the mistake: the area, not 1 / area
}

}  // namespace raylab
