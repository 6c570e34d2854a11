// Stage 02_sphere: where a ray first meets a sphere.            Handout: docs/02_sphere.md
//
// WHAT YOU RECEIVE
//   ray.origin, ray.direction   the ray's points are origin + t * direction. The direction is
//                               NOT necessarily unit length.
//   ray.t_min, ray.t_max        only hits with t_min < t < t_max count (both ends excluded)
//   sphere_center, sphere_radius   the sphere, radius > 0
//
// WHAT YOU RETURN
//   The SMALLEST t with t_min < t < t_max at which the ray meets the sphere's surface, or
//   std::nullopt when there is none. The origin may be inside the sphere.
//
// READ docs/02_sphere.md: section 2 (the quadratic and a worked example), section 3 (how
//   to compute its roots without losing digits: the bonus stage 06_robustness grades that),
//   section 4 (common mistakes, which the autograder's hints name).
//
// HOW TO CHECK
//   build/bin/autograder --stage 02_sphere
#include "raylab/error.h"
#include "raylab/stages/02_sphere.h"

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center,
                                          float sphere_radius) {
  (void)ray;
  (void)sphere_center;
  (void)sphere_radius;
  // Delete the line below when you write the function.
  throw NotImplemented("intersect_ray_sphere");
}

}  // namespace raylab
