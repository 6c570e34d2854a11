// Grader self-test submission (stage 02_sphere): mistake: no test of the discriminant. On a
// miss std::sqrt of a negative number is NaN, every rejecting comparison with NaN is false,
// so the function returns t = NaN as a hit. The report must say "returns NaN".
#include "sphere_variant.h"

#include "raylab/stages/02_sphere.h"

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  const submission::SphereRoots roots = submission::robust_sphere_roots(ray, sphere_center, sphere_radius);
  float t = roots.t_near;  // the mistake: roots.discriminant is never tested
  if (t <= ray.t_min) t = roots.t_far;
  if (t <= ray.t_min || t >= ray.t_max) return std::nullopt;
  return t;
}

}  // namespace raylab
