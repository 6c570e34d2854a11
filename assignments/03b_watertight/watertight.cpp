// Bonus stage 06_robustness (folder 03b_watertight): a ray-triangle test without leaks.   Handout: docs/03b_watertight.md
//
// WHY
//   Moller-Trumbore (stage 03) decides "inside" from b1, b2 and b1 + b2, each rounded on its
//   own. A ray through the edge shared by two triangles can then come out slightly outside
//   BOTH of them: it slips through a closed mesh ("leaks"), and a light ray reaches a point
//   that should be in shadow. Woop, Benthin and Wald (JCGT 2013) test every edge with the
//   same expression, rounded the same way, from both triangles that share it, so that a ray
//   can never be outside both. Graded by the bonus stage 06_robustness.
//
// WHAT YOU RECEIVE
//   ray.origin, ray.direction   points origin + t * direction; direction not necessarily unit
//                               (and possibly zero: then nothing is hit)
//   ray.t_min, ray.t_max        only hits with t_min < t < t_max count
//   p0, p1, p2                  the triangle's corners (world space), in either winding
//
// WHAT YOU RETURN
//   Exactly what stage 03 returns: TriangleHit{t_hit, barycentric_b1, barycentric_b2} for a
//   hit from EITHER side, inside or on an edge, with t_min < t_hit < t_max; else
//   std::nullopt (also for a ray parallel to the triangle or a triangle without area).
//   origin + t_hit * direction = (1 - b1 - b2) p0 + b1 p1 + b2 p2. Never NaN.
//   The promise beyond stage 03's: a ray through an edge or corner shared by triangles of a
//   closed mesh hits at least one of them.
//
// READ docs/03b_watertight.md: section 2 (the algorithm, step by step), section 3
//   (numerical care and common mistakes, which the autograder's hints name), section 4 (the
//   bound on t's rounding error: reject t_hit <= delta_t, or rays leaving a large triangle
//   hit it again; graded by 06_robustness as shadow acne).
//
// HOW TO CHECK
//   build/bin/autograder --stage 06_robustness     (the bonus stage 06_robustness shoots a million
//   rays through the edges and corners of closed meshes and counts the ones that get through)
#include "raylab/error.h"
#include "raylab/stages/03b_watertight.h"

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle_watertight(const Ray& ray, const glm::vec3& p0,
                                                             const glm::vec3& p1, const glm::vec3& p2) {
  (void)ray;
  (void)p0;
  (void)p1;
  (void)p2;
  // Delete the line below when you write the function.
  throw NotImplemented("intersect_ray_triangle_watertight");
}

}  // namespace raylab
