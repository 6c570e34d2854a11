// The reference's slab test (stage 04_box), as an inline function: solutions/04_box/box.cpp
// wraps it as the stage function, and the reference traversal (solutions/05_bvh/bvh.cpp)
// calls it directly, so that its box tests are inlined instead of a call each. Not part of
// any student contract (students write intersect_ray_box; their traversal calls it).
#pragma once

#include "raylab/bounds.h"
#include "raylab/math.h"

namespace raylab::reference {

// One slab: narrows [t_enter, t_exit] to the part of the ray between two parallel planes.
// The entry plane is chosen by the sign of the inverse direction (1 / -0 = -infinity counts as
// negative), so the two distances are never compared with each other. The only NaN possible
// is 0 * infinity (the origin exactly on a plane, the ray parallel to it); `>` and `<` are
// false for NaN, so it leaves the interval as it was: the ray lying in a face is a hit.
inline void clip_to_slab(float origin, float inverse, float slab_min, float slab_max,
                         float& t_enter, float& t_exit) {
  const bool negative = inverse < 0.0f;
  const float entry = ((negative ? slab_max : slab_min) - origin) * inverse;
  // Ize 2013: the rounded exit distance may be up to 2 gamma(3) too small; scaling it up
  // keeps the test conservative, so a BVH never loses a hit on a box's edge.
  const float exit = ((negative ? slab_min : slab_max) - origin) * inverse * (1.0f + 2.0f * gamma_bound(3));
  if (entry > t_enter) t_enter = entry;
  if (exit < t_exit) t_exit = exit;
}

// The box test of stage 04_box: true if the ray's points with t in [t_min, t_max] meet the
// closed box; then t_enter = max(entry distance, t_min).
inline bool ray_enters_box(const glm::vec3& origin, const glm::vec3& ray_direction_inverse,
                           const Bounds3& box, float t_min, float t_max, float& t_enter) {
  float enter = t_min, exit = t_max;
  clip_to_slab(origin.x, ray_direction_inverse.x, box.min.x, box.max.x, enter, exit);
  clip_to_slab(origin.y, ray_direction_inverse.y, box.min.y, box.max.y, enter, exit);
  clip_to_slab(origin.z, ray_direction_inverse.z, box.min.z, box.max.z, enter, exit);
  t_enter = enter;
  return enter <= exit;
}

}  // namespace raylab::reference
