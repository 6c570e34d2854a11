// Reference solution, stage 02_sphere. The contract is in assignments/02_sphere/sphere.cpp and
// docs/02_sphere.md.
#include "raylab/stages/02_sphere.h"

#include <cmath>
#include <utility>

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center,
                                          float sphere_radius) {
  const glm::vec3& d = ray.direction;
  const glm::vec3 center_to_origin = ray.origin - sphere_center;
  const float a = glm::dot(d, d);
  if (!(a > 0.0f)) return std::nullopt;  // zero (or NaN) direction: no ray at all
  const float b = 2.0f * glm::dot(center_to_origin, d);
  const float c = glm::dot(center_to_origin, center_to_origin) - sphere_radius * sphere_radius;

  // b^2 - 4ac loses every digit when the sphere is small and far away. The same number,
  // computed from the distance between the centre and the ray's line, keeps them
  // (Haines et al., Ray Tracing Gems, ch. 7): b^2 - 4ac = 4a (r^2 - |perpendicular|^2).
  const glm::vec3 perpendicular = center_to_origin - (glm::dot(center_to_origin, d) / a) * d;
  const float discriminant =
      4.0f * a * (sphere_radius * sphere_radius - glm::dot(perpendicular, perpendicular));
  if (!(discriminant >= 0.0f)) return std::nullopt;

  // The stable pair of roots: never subtract two nearly equal numbers.
  const float root = std::sqrt(discriminant);
  const float q = b < 0.0f ? -0.5f * (b - root) : -0.5f * (b + root);
  float t_near = q / a;
  float t_far = q != 0.0f ? c / q : t_near;
  if (t_near > t_far) std::swap(t_near, t_far);

  if (t_near > ray.t_min && t_near < ray.t_max) return t_near;
  if (t_far > ray.t_min && t_far < ray.t_max) return t_far;  // the origin is inside
  return std::nullopt;
}

}  // namespace raylab
