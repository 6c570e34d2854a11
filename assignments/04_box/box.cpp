// Stage 04_box: a ray against an axis-aligned box (the slab test).      Handout: docs/04_box.md
//
// WHAT YOU RECEIVE
//   ray.origin, ray.direction   points origin + t * direction; direction not necessarily unit,
//                               and any component may be 0 (even -0.0f)
//   ray.t_min, ray.t_max        the part of the ray that counts: t in [t_min, t_max]. During a
//                               BVH traversal t_max is the closest hit found so far.
//   ray_direction_inverse       (1 / direction.x, 1 / direction.y, 1 / direction.z), computed ONCE
//                               per ray by the caller: multiply by it, never divide in here.
//                               A zero component gives +infinity (for +0) or -infinity (for -0).
//   box.min, box.max            the closed box's corners, min <= max on every axis. A flat box
//                               (min == max on some axis) is allowed: a triangle in z = 0 has one.
//
// WHAT YOU RETURN
//   The distance at which the ray enters the box, clipped to the ray's interval:
//   max(t_enter, t_min), when some point with t in [t_min, t_max] is inside the box or on its
//   surface; std::nullopt when none is. So: the origin inside the box returns t_min; a box
//   wholly behind the ray (t_exit < t_min) or beyond t_max (t_enter > t_max) returns nullopt.
//
// THE SLABS (docs/04_box.md, section 2)
//   The box is the intersection of three slabs, e.g. min.x <= x <= max.x. Along the ray, the
//   x slab is crossed between t = (min.x - origin.x) * inverse.x and (max.x - origin.x) *
//   inverse.x; the smaller of the two is where the ray enters the slab, the larger where it
//   leaves (when inverse.x < 0, the max.x plane is met first). The ray is inside the box when
//   it is inside all three slabs and inside [t_min, t_max] at once:
//     t_enter = max(entry x, entry y, entry z, t_min)
//     t_exit  = min(exit x,  exit y,  exit z,  t_max)
//     hit when t_enter <= t_exit (<=, not <: a ray grazing an edge, or a flat box, is a hit).
//
// ZERO DIRECTION COMPONENTS (section 3): IEEE 754 does the work if you let it.
//   direction.x == 0: inverse.x = +-infinity, and a slab entry/exit is +-infinity: the ray
//   never enters (origin outside the slab) or never leaves (inside). But an origin EXACTLY on
//   a slab plane gives 0 * infinity = NaN. Every comparison with NaN is false, so write the
//   max/min above as `if (entry > t_enter) t_enter = entry;` (and the same with < for t_exit):
//   then a NaN never replaces a number, and the ray lying in a face of the box is a hit.
//   Pick which plane is the entry by the sign of inverse.x, not by comparing the two ts
//   (that comparison is where a NaN would sneak in).
//
// ROUNDING (section 4, Ize 2013): the computed t_exit can come out a little too small, so a
//   ray grazing a box could miss it and a BVH would lose a hit. Multiply each exit distance by
//   (1 + 2 * gamma_bound(3)) (raylab/math.h) to keep the test conservative.
//
// COMMON MISTAKES
//   dividing by direction (slow, and 1 / -0 must stay -infinity: do not "fix" zeros with an
//   epsilon); forgetting to swap entry and exit when the direction is negative; forgetting
//   t_min / t_max; returning t_enter below t_min (a box around the origin must return t_min);
//   using std::max / std::min with a NaN in the wrong argument.
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
  // Start with the x slab's entry and exit above. Delete the line below when you are done.
  throw NotImplemented("intersect_ray_box");
}

}  // namespace raylab
