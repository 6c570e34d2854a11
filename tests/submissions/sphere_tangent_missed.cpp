// Grader self-test submission (stage 02_sphere): mistake: a tangent ray (discriminant exactly 0)
// treated as a miss (discriminant <= 0 rejected); every other ray right. The contract counts a
// ray that meets the surface at one point as a hit.
#include "sphere_variant.h"

#include "raylab/stages/02_sphere.h"

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  if (!(glm::dot(ray.direction, ray.direction) > 0.0f)) return std::nullopt;
  const submission::SphereRoots roots = submission::robust_sphere_roots(ray, sphere_center, sphere_radius);
  if (!(roots.discriminant > 0.0f)) return std::nullopt;  // the mistake: a graze is a hit
  if (roots.t_near > ray.t_min && roots.t_near < ray.t_max) return roots.t_near;
  if (roots.t_far > ray.t_min && roots.t_far < ray.t_max) return roots.t_far;
  return std::nullopt;
}

}  // namespace raylab
