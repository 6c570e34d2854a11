// Grader self-test submission (stage 02_sphere): mistake: a tangent ray (discriminant exactly 0)
// treated as a miss (discriminant <= 0 rejected); every other ray right. The contract counts a
// ray that meets the surface at one point as a hit.
#include "raylab/stages/02_sphere.h"

#include <cmath>
#include <utility>

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  const glm::vec3& d = ray.direction;
  const glm::vec3 oc = ray.origin - sphere_center;
  const float a = glm::dot(d, d);
  if (!(a > 0.0f)) return std::nullopt;
  const float b = 2.0f * glm::dot(oc, d);
  const float c = glm::dot(oc, oc) - sphere_radius * sphere_radius;
  const glm::vec3 perpendicular = oc - (glm::dot(oc, d) / a) * d;
  const float discriminant = 4.0f * a * (sphere_radius * sphere_radius - glm::dot(perpendicular, perpendicular));
  if (!(discriminant > 0.0f)) return std::nullopt;  // the mistake: a graze is a hit
  const float root = std::sqrt(discriminant);
  const float q = b < 0.0f ? -0.5f * (b - root) : -0.5f * (b + root);
  float t_near = q / a, t_far = q != 0.0f ? c / q : t_near;
  if (t_near > t_far) std::swap(t_near, t_far);
  if (t_near > ray.t_min && t_near < ray.t_max) return t_near;
  if (t_far > ray.t_min && t_far < ray.t_max) return t_far;
  return std::nullopt;
}

}  // namespace raylab
