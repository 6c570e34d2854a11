// Stage 04_box: a ray against an axis-aligned box (the slab test).      Handout: docs/04_box.md
//
// WHAT YOU RECEIVE
//   ray.origin, ray.direction   points origin + t * direction; direction not necessarily unit,
//                               and any component may be 0 (even -0.0f)
//   ray.t_min, ray.t_max        the part of the ray that counts: t in [t_min, t_max] (ends
//                               included). During a BVH traversal t_max is the closest hit so far.
//   ray_direction_inverse       (1 / direction.x, 1 / direction.y, 1 / direction.z), computed ONCE
//                               per ray by the caller: multiply by it rather than divide (faster).
//                               A zero component gives +infinity (for +0) or -infinity (for -0).
//   box.min, box.max            the closed box's corners, min <= max on every axis. A flat box
//                               (min == max on some axis) is allowed: a triangle in z = 0 has one.
//
// WHAT YOU RETURN
//   The distance at which the ray enters the box, clipped to the ray's interval:
//   max(t_enter, t_min), when some point with t in [t_min, t_max] is inside the box or on its
//   surface (grazing an edge or a face counts); std::nullopt when none is. So the origin
//   inside the box returns t_min; a box wholly behind the ray or beyond t_max returns nullopt.
//   It must never lose a hit: a BVH traversal that trusts it would miss the primitives inside.
//   That holds for zero direction components (also with the origin exactly on a face plane,
//   where IEEE 754 gives 0 * infinity = NaN) and under rounding.
//
// READ docs/04_box.md: section 2 (slabs), section 3 (zero direction components, NaN and
//   other boundary cases), section 4 (rounding: a conservative exit, Ize 2013; gamma_bound is
//   in raylab/math.h), section 5 (common mistakes, which the autograder's hints name).
//
// HOW TO CHECK
//   build/bin/autograder --stage 04_box
#include "raylab/error.h"
#include "raylab/stages/04_box.h"

namespace raylab {

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse,
                                       const Bounds3& box) {
  (void)ray;
  (void)ray_direction_inverse;
  (void)box;
  // Delete the line below when you write the function.
  throw NotImplemented("intersect_ray_box");
}

}  // namespace raylab
