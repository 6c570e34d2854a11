// Grader self-test submission (stage 04_box): the reference slab test without Ize's
// conservative exit factor. Right on every stage 04 case; but rays aimed exactly at a box's
// edge are rounded into misses, which the bonus stage 06_robustness must see.
#include "raylab/stages/04_box.h"

namespace raylab {
namespace {

// One slab: narrows [t_enter, t_exit] to the part of the ray between two parallel planes.
// The entry plane is chosen by the sign of the inverse direction (1 / -0 = -infinity counts as
// negative), so the two distances are never compared with each other. The only NaN possible
// is 0 * infinity (the origin exactly on a plane, the ray parallel to it); `>` and `<` are
// false for NaN, so it leaves the interval as it was: the ray lying in a face is a hit.
inline void clip_to_slab(float origin, float inverse, float slab_min, float slab_max,
                         float& t_enter, float& t_exit) {
  const bool negative = inverse < 0.0f;
  const float entry = ((negative ? slab_max : slab_min) - origin) * inverse;
  const float exit = ((negative ? slab_min : slab_max) - origin) * inverse;  // MISTAKE: no Ize factor
  if (entry > t_enter) t_enter = entry;
  if (exit < t_exit) t_exit = exit;
}

}  // namespace

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse,
                                       const Bounds3& box) {
  float t_enter = ray.t_min;
  float t_exit = ray.t_max;
  clip_to_slab(ray.origin.x, ray_direction_inverse.x, box.min.x, box.max.x, t_enter, t_exit);
  clip_to_slab(ray.origin.y, ray_direction_inverse.y, box.min.y, box.max.y, t_enter, t_exit);
  clip_to_slab(ray.origin.z, ray_direction_inverse.z, box.min.z, box.max.z, t_enter, t_exit);
  if (t_enter <= t_exit) return t_enter;
  return std::nullopt;
}

}  // namespace raylab
