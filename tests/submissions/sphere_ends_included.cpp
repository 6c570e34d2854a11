// Grader self-test submission (stage 02_sphere), broken: the interval's ends included (t >= t_min,
// t <= t_max), where the contract excludes both: a root exactly at t_min or t_max counts.
#include "sphere_variant.h"

#include "raylab/stages/02_sphere.h"

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  const submission::SphereRoots roots = submission::robust_sphere_roots(ray, sphere_center, sphere_radius);
  if (roots.discriminant < 0.0f) return std::nullopt;
  for (const float t : {roots.t_near, roots.t_far})
    if (t >= ray.t_min && t <= ray.t_max) return t;  // the mistake: >= and <=
  return std::nullopt;
}

}  // namespace raylab
