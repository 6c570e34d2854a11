// Stage 03_triangle: where a ray meets a triangle (Moller-Trumbore).   Handout: docs/03_triangle.md
//
// WHAT YOU RECEIVE
//   ray.origin, ray.direction   points origin + t * direction; direction not necessarily unit
//   ray.t_min, ray.t_max        only hits with t_min < t < t_max count
//   p0, p1, p2                  the triangle's corners (world space), in either winding
//
// WHAT YOU RETURN
//   TriangleHit{t_hit, barycentric_b1, barycentric_b2} when the ray meets the triangle inside
//   or on its edges, from EITHER side (no back-face culling), with t_min < t_hit < t_max;
//   std::nullopt otherwise, also for a ray parallel to the triangle's plane or a triangle
//   without area. The barycentrics say where the point is:
//     origin + t_hit * direction = (1 - b1 - b2) * p0 + b1 * p1 + b2 * p2
//   so b1 is p1's weight and b2 is p2's (the floor's checkerboard is read with them).
//
// READ docs/03_triangle.md: section 2 (solving that equation for t, b1 and b2, with worked
//   examples), section 3 (zero determinants and NaN), section 4 (common mistakes, which the
//   autograder's hints name).
//
// HOW TO CHECK
//   build/bin/autograder --stage 03_triangle
#include "raylab/error.h"
#include "raylab/stages/03_triangle.h"

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0,
                                                  const glm::vec3& p1, const glm::vec3& p2) {
  (void)ray;
  (void)p0;
  (void)p1;
  (void)p2;
  // Delete the line below when you write the function.
  throw NotImplemented("intersect_ray_triangle");
}

}  // namespace raylab
