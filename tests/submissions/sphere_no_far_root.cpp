// Grader self-test submission (stage 02_sphere): mistake: only the near root; misses when the origin is inside
#include "raylab/stages/02_sphere.h"

#include <cmath>

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  const glm::vec3 oc = ray.origin - sphere_center;
  const float a = glm::dot(ray.direction, ray.direction);
  const float b = 2.0f * glm::dot(oc, ray.direction);
  const float c = glm::dot(oc, oc) - sphere_radius * sphere_radius;
  const float discriminant = b * b - 4.0f * a * c;
  if (discriminant < 0.0f) return std::nullopt;
  const float t_near = (-b - std::sqrt(discriminant)) / (2.0f * a);
  const float t_far = (-b + std::sqrt(discriminant)) / (2.0f * a);
  (void)t_far;
  if (t_near > ray.t_min && t_near < ray.t_max) return t_near;
  return std::nullopt;
}

}  // namespace raylab
