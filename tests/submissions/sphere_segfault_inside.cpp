// Grader self-test submission (stage 02_sphere): crashes (null pointer write) whenever the origin is inside the sphere
#include "sphere_variant.h"

#include "raylab/stages/02_sphere.h"

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  const submission::SphereRoots roots = submission::robust_sphere_roots(ray, sphere_center, sphere_radius);
  if (roots.discriminant < 0.0f) return std::nullopt;
  if (roots.t_near < 0.0f && roots.t_far > 0.0f) {
    volatile int* nowhere = nullptr;
    *nowhere = 1;  // the deliberate crash
  }
  if (roots.t_near > ray.t_min && roots.t_near < ray.t_max) return roots.t_near;
  if (roots.t_far > ray.t_min && roots.t_far < ray.t_max) return roots.t_far;
  return std::nullopt;
}

}  // namespace raylab
