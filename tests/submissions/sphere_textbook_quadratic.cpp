// Grader self-test submission (stage 02_sphere): the TEXTBOOK quadratic, b^2 - 4ac and
// (-b -+ sqrt(disc)) / 2a. Right on ordinary spheres; loses digits to catastrophic
// cancellation on small, far spheres and near huge ones (bonus stage 06_robustness).
#include "raylab/stages/02_sphere.h"

#include <cmath>

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  const glm::vec3 oc = ray.origin - sphere_center;
  const float a = glm::dot(ray.direction, ray.direction);
  const float b = 2.0f * glm::dot(oc, ray.direction);
  const float c = glm::dot(oc, oc) - sphere_radius * sphere_radius;
  const float discriminant = b * b - 4.0f * a * c;
  if (!(a > 0.0f) || !(discriminant >= 0.0f)) return std::nullopt;
  const float root = std::sqrt(discriminant);
  const float t_near = (-b - root) / (2.0f * a);
  const float t_far = (-b + root) / (2.0f * a);
  if (t_near > ray.t_min && t_near < ray.t_max) return t_near;
  if (t_far > ray.t_min && t_far < ray.t_max) return t_far;
  return std::nullopt;
}

}  // namespace raylab
