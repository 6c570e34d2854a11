// Stage 03b_watertight (bonus): a ray-triangle test without leaks.   Handout: docs/03b_watertight.md
//
// WHY
//   Moller-Trumbore (stage 03) decides "inside" from b1, b2 and b1 + b2, each rounded on its
//   own. A ray through the edge shared by two triangles can then come out slightly outside
//   BOTH of them: it slips through a closed mesh ("leaks"), and a light ray reaches a point
//   that should be in shadow. Woop, Benthin and Wald (JCGT 2013) transform the triangle into a
//   space where the ray is the +z axis through (0, 0). Each edge is then tested by the SAME
//   2D expression, with the same rounding, from both triangles that share it (only its sign
//   flips), so a ray can never be outside both.
//
// WHAT YOU RECEIVE
//   ray.origin, ray.direction   points origin + t * direction; direction not necessarily unit
//   ray.t_min, ray.t_max        only hits with t_min < t < t_max count
//   p0, p1, p2                  the triangle's corners (world space), in either winding
//
// WHAT YOU RETURN
//   Exactly what stage 03 returns: TriangleHit{t_hit, barycentric_b1, barycentric_b2} for a
//   hit from EITHER side, inside or on an edge, with t_min < t_hit < t_max; else
//   std::nullopt. origin + t_hit * direction = (1 - b1 - b2) p0 + b1 p1 + b2 p2.
//
// THE ALGORITHM (docs/03b_watertight.md, section 2)
//   1. kz = the axis where |direction| is largest; kx = (kz + 1) % 3, ky = (kx + 1) % 3.
//      (The paper also swaps kx and ky when direction[kz] < 0, to keep the winding: optional
//      here, since both faces count.)
//   2. shear_x = -d[kx] / d[kz], shear_y = -d[ky] / d[kz], shear_z = 1 / d[kz].
//   3. For each corner p: a = p - origin, then in 2D
//        x = a[kx] + shear_x * a[kz],   y = a[ky] + shear_y * a[kz],   z = shear_z * a[kz]
//      (compute each corner's x and y exactly like this, so that a corner shared by two
//      triangles gets the same numbers in both).
//   4. Edge functions (twice the signed areas seen from the ray):
//        u = x2 * y1 - y2 * x1   (edge p1-p2; weight of p0)
//        v = x0 * y2 - y0 * x2   (edge p2-p0; weight of p1)
//        w = x1 * y0 - y1 * x0   (edge p0-p1; weight of p2)
//      If u, v or w is exactly 0, recompute all three in double: the float product may
//      have rounded a tiny non-zero area to 0, and the sign decides.
//   5. Miss if the signs differ: (u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0).
//   6. det = u + v + w; det == 0 (or not finite) is a miss (parallel ray, degenerate triangle).
//   7. t_hit = (u * z0 + v * z1 + w * z2) / det; keep it only if t_min < t_hit < t_max.
//      barycentric_b1 = v / det, barycentric_b2 = w / det.
//   8. Optional (not graded; section 3): also reject t_hit <= its rounding-error bound, as
//      pbrt-v4 does, or shadow rays leaving a large triangle may hit it again (shadow acne
//      when you render with --watertight).
//
// COMMON MISTAKES
//   computing a corner's 2D position differently in different triangles (e.g. from
//   edge vectors p1 - p0): the shared edge no longer gets the same rounding and the leaks come
//   back; forgetting the double-precision retry when an edge function is 0; rejecting det < 0
//   (that culls back faces); returning u / det as b1 (u is p0's weight); NaN from a zero
//   direction component on the kz axis (kz is the LARGEST component, so d[kz] != 0 unless the
//   whole direction is zero: then return std::nullopt).
//
// HOW TO CHECK
//   build/bin/autograder --stage 06_robustness     (the bonus stage 06_robustness shoots a million rays
//   through the edges and corners of closed meshes and counts the ones that get through)
#include "raylab/error.h"
#include "raylab/stages/03b_watertight.h"

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle_watertight(const Ray& ray, const glm::vec3& p0,
                                                             const glm::vec3& p1, const glm::vec3& p2) {
  (void)ray;
  (void)p0;
  (void)p1;
  (void)p2;
  // Start with kz and the shear in steps 1-2 above. Delete the line below when you are done.
  throw NotImplemented("intersect_ray_triangle_watertight");
}

}  // namespace raylab
