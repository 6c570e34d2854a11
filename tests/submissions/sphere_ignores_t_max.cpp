// Grader self-test submission (stage 02_sphere): mistake: t_max ignored
#include "sphere_variant.h"

#include "raylab/stages/02_sphere.h"

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  const submission::SphereRoots roots = submission::robust_sphere_roots(ray, sphere_center, sphere_radius);
  if (roots.discriminant < 0.0f) return std::nullopt;
  if (roots.t_near > ray.t_min) return roots.t_near;  // the mistake: no t < t_max
  if (roots.t_far > ray.t_min) return roots.t_far;
  return std::nullopt;
}

}  // namespace raylab
