// Grader self-test submission (stage 07_sampling): correct warps other than the reference's
// (polar maps instead of the concentric disk, z^2 uniform for the cosine hemisphere, the
// folded square for the triangle, z = u rather than 1 - u) and densities written another way:
// full marks.
#include "raylab/stages/07_sampling.h"

#include <cmath>

namespace raylab {
namespace {
constexpr float kTwoPi = 6.28318530717958647692f;

glm::vec3 direction_from(float z, float phi) {
  const float radius = std::sqrt(std::fmax(0.0f, 1.0f - z * z));
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}
}  // namespace

glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random) {
  return direction_from(uniform_random.x, kTwoPi * uniform_random.y);
}

float uniform_hemisphere_pdf(const glm::vec3& direction) { return direction.z < 0.0f ? 0.0f : 0.5f / 3.14159265f; }

glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random) {
  return direction_from(std::sqrt(uniform_random.x), kTwoPi * uniform_random.y);
}

float cosine_hemisphere_pdf(const glm::vec3& direction) { return std::fmax(0.0f, direction.z) * 0.318309886f; }

glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random) {
  return direction_from(2.0f * uniform_random.x - 1.0f, kTwoPi * uniform_random.y);
}

float uniform_sphere_pdf(const glm::vec3&) { return 0.0795774715f; }

glm::vec2 sample_uniform_disk(glm::vec2 uniform_random) {
  const float radius = std::sqrt(uniform_random.x), phi = kTwoPi * uniform_random.y;
  return glm::vec2(radius * std::cos(phi), radius * std::sin(phi));
}

float uniform_disk_pdf(glm::vec2 point) { return point.x * point.x + point.y * point.y > 1.0f ? 0.0f : 0.318309886f; }

Barycentrics sample_uniform_triangle(glm::vec2 uniform_random) {
  if (uniform_random.x + uniform_random.y > 1.0f) return Barycentrics{1.0f - uniform_random.x, 1.0f - uniform_random.y};
  return Barycentrics{uniform_random.x, uniform_random.y};
}

float uniform_triangle_pdf(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  const glm::vec3 normal = glm::cross(p1 - p0, p2 - p0);
  return 2.0f / std::sqrt(glm::dot(normal, normal));
}

}  // namespace raylab
