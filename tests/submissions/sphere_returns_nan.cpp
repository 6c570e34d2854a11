// Grader self-test submission (stage 02_sphere): mistake: no test of the discriminant. On a
// miss std::sqrt of a negative number is NaN, every rejecting comparison with NaN is false,
// so the function returns t = NaN as a hit. The report must say "returns NaN".
#include "raylab/stages/02_sphere.h"

#include <cmath>

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  const glm::vec3 oc = ray.origin - sphere_center;
  const float a = glm::dot(ray.direction, ray.direction);
  const float b = 2.0f * glm::dot(oc, ray.direction);
  const float c = glm::dot(oc, oc) - sphere_radius * sphere_radius;
  const float root = std::sqrt(b * b - 4.0f * a * c);
  float t = (-b - root) / (2.0f * a);
  if (t <= ray.t_min) t = (-b + root) / (2.0f * a);
  if (t <= ray.t_min || t >= ray.t_max) return std::nullopt;
  return t;
}

}  // namespace raylab
