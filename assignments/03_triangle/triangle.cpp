// Stage 03_triangle: where a ray meets a triangle (Moller-Trumbore).   Handout: docs/03_triangle.md
//
// WHAT YOU RECEIVE
//   ray.origin, ray.direction   points origin + t * direction; direction not necessarily unit
//   ray.t_min, ray.t_max        only hits with t_min < t < t_max count
//   p0, p1, p2                  the triangle's corners (world space), in either winding
//
// WHAT YOU RETURN
//   TriangleHit{t_hit, barycentric_b1, barycentric_b2} when the ray meets the triangle inside
//   or on its edges, from EITHER side, with t_min < t_hit < t_max; std::nullopt otherwise.
//   The barycentrics say where the point is:
//     origin + t_hit * direction = (1 - b1 - b2) * p0 + b1 * p1 + b2 * p2
//   so b1 is p1's weight and b2 is p2's (the floor's checkerboard is read with them).
//
// THE MATH (docs/03_triangle.md, section 2): solve the equation above for (t, b1, b2).
//     edge_01 = p1 - p0,  edge_02 = p2 - p0,  s = origin - p0
//     s1 = cross(direction, edge_02),  s2 = cross(s, edge_01),  det = dot(s1, edge_01)
//     t_hit = dot(s2, edge_02) / det,  b1 = dot(s1, s) / det,  b2 = dot(s2, direction) / det
//   det == 0 means the ray is parallel to the triangle's plane (or the triangle has no
//   area): no hit.  Inside means b1 >= 0, b2 >= 0 and b1 + b2 <= 1.
//
// COMMON MISTAKES
//   accepting t < t_min (hits behind the ray); accepting points outside the triangle (forgot
//   b1 + b2 <= 1); swapping b1 and b2 (the checkerboard comes out mirrored); dividing by a
//   zero determinant; culling back faces (this course hits both faces).
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
  // Start with edge_01, edge_02 and s1 above. Delete the line below when you are done.
  throw NotImplemented("intersect_ray_triangle");
}

}  // namespace raylab
