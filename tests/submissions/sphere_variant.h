// Grader self-test submissions of stage 02_sphere share these roots: the quadratic solved without
// cancellation (docs/02_sphere.md, section 3), so that a submission whose mistake is elsewhere
// (which root it returns, t_max, a crash) is as precise as stage 06_robustness asks, and loses
// points at stage 02 only. Each submission picks its root from them, with its mistake.
#pragma once

#include "raylab/ray.h"

#include <cmath>
#include <utility>

namespace raylab::submission {

struct SphereRoots {
  float discriminant;   // of a t^2 + b t + c = 0, from the distance between the centre and the line
  float t_near, t_far;  // NaN when the discriminant is negative (std::sqrt of it)
};

// unit_direction: the mistake of taking a = |d|^2 as 1 (then the discriminant is b^2 - 4c).
inline SphereRoots robust_sphere_roots(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius,
                                       bool unit_direction = false) {
  const glm::vec3& d = ray.direction;
  const glm::vec3 oc = ray.origin - sphere_center;
  const float a = unit_direction ? 1.0f : glm::dot(d, d);
  const float b = 2.0f * glm::dot(oc, d);
  const float c = glm::dot(oc, oc) - sphere_radius * sphere_radius;
  const glm::vec3 perpendicular = oc - (glm::dot(oc, d) / a) * d;
  const float discriminant = unit_direction ? b * b - 4.0f * c
                                            : 4.0f * a * (sphere_radius * sphere_radius - glm::dot(perpendicular, perpendicular));
  const float root = std::sqrt(discriminant);
  const float q = b < 0.0f ? -0.5f * (b - root) : -0.5f * (b + root);
  float t_near = q / a, t_far = q != 0.0f ? c / q : t_near;
  if (t_near > t_far) std::swap(t_near, t_far);
  return {discriminant, t_near, t_far};
}

}  // namespace raylab::submission
