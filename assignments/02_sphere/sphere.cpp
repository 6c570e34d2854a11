// Stage 02_sphere: where a ray first meets a sphere.            Handout: docs/02_sphere.md
//
// WHAT YOU RECEIVE
//   ray.origin, ray.direction   the ray's points are origin + t * direction. The direction is
//                               NOT necessarily unit length: do not assume dot(d, d) == 1.
//   ray.t_min, ray.t_max        only hits with t_min < t < t_max count (both ends excluded)
//   sphere_center, sphere_radius   the sphere, radius > 0
//
// WHAT YOU RETURN
//   The SMALLEST t with t_min < t < t_max at which the ray meets the sphere's surface, or
//   std::nullopt when there is none. If the origin is inside the sphere, the near root is
//   behind the ray (t < 0), so the answer is the FAR root.
//
// THE MATH (docs/02_sphere.md, section 2)
//   |origin + t d - center|^2 = R^2 is the quadratic a t^2 + b t + c = 0 with
//     a = dot(d, d),  b = 2 dot(origin - center, d),  c = dot(origin - center, origin - center) - R^2
//   discriminant = b^2 - 4ac: negative means the ray misses. Compute the two roots in the
//   numerically stable form (section 3):  q = -(b + sign(b) sqrt(discriminant)) / 2,
//   t0 = q / a, t1 = c / q, then order them so that t0 <= t1.
//
// COMMON MISTAKES
//   returning a hit behind the ray (t <= t_min); missing the far root when the origin is
//   inside; ignoring t_max; assuming a unit direction (a = 1).
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
  // Start with a, b and c above. Delete the line below when you are done.
  throw NotImplemented("intersect_ray_sphere");
}

}  // namespace raylab
