// Hostile: sphere_segfault_inside, but exit(0) instead of the crash when the ray starts inside
// the sphere. A clean exit delivers no answer either: it must score exactly what
// sphere_segfault_inside scores, with the reason "exited (status 0)".
#include "raylab/stages/02_sphere.h"

#include <cmath>
#include <cstdlib>

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
  if (t_near < 0.0f && t_far > 0.0f) std::exit(0);  // the deliberate exit
  if (t_near > ray.t_min && t_near < ray.t_max) return t_near;
  if (t_far > ray.t_min && t_far < ray.t_max) return t_far;
  return std::nullopt;
}

}  // namespace raylab
