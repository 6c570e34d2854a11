// Grader self-test submission (stage 07_sampling): five more mistakes, one per warp, each
// named: the uniform hemisphere cosine-weighted, the cosine hemisphere's directions not unit
// length, the sphere's directions only above z = 0, the disk's pdf of another shape (it
// integrates to 1), barycentrics that leave the triangle.
#include "raylab/stages/07_sampling.h"

#include "raylab/math.h"

#include <algorithm>
#include <cmath>

namespace raylab {

glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random) {
  // z = cos(theta) is uniform in [0, 1] (Archimedes: equal heights, equal areas).
  const float z = std::sqrt(uniform_random.x);  // the mistake: cosine-weighted
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * uniform_random.y;
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

float uniform_hemisphere_pdf(const glm::vec3& direction) { return direction.z >= 0.0f ? 1.0f / (2.0f * kPi) : 0.0f; }

glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random) {
  // Malley's method: a uniform point of the disk, lifted onto the hemisphere.
  const glm::vec2 disk = sample_uniform_disk(uniform_random);
  const float z = std::sqrt(std::max(0.0f, 1.0f - disk.x * disk.x - disk.y * disk.y));
  (void)z;
  return glm::vec3(disk.x, disk.y, 1.0f);  // the mistake: not normalised
}

float cosine_hemisphere_pdf(const glm::vec3& direction) { return direction.z > 0.0f ? direction.z / kPi : 0.0f; }

glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random) {
  const float z = 1.0f - uniform_random.x;  // the mistake: only z > 0
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
  if (offset.x == 0.0f && offset.y == 0.0f) return glm::vec2(0.0f);
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

float uniform_disk_pdf(glm::vec2 point) {
  // the mistake: a density that integrates to 1 but is not the samples' one
  return glm::dot(point, point) <= 1.0f ? 2.0f * (1.0f - glm::dot(point, point)) / kPi : 0.0f;
}

Barycentrics sample_uniform_triangle(glm::vec2 uniform_random) {
  // The square-root warp (pbrt-v4, section A.5.5): sqrt(u.x) is the distance from p0 towards
  // the opposite edge (area grows with its square), u.y the position along that edge.
  return Barycentrics{uniform_random.x, uniform_random.y};  // the mistake: b1 + b2 can exceed 1
}

float uniform_triangle_pdf(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  const float twice_area = glm::length(glm::cross(p1 - p0, p2 - p0));
  return twice_area > 0.0f ? 2.0f / twice_area : 0.0f;
}

}  // namespace raylab
