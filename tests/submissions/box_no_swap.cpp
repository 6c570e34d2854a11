// Grader self-test submission (stage 04_box): mistake: no swap for a negative direction
// component, so each axis's (min - o) * inverse is taken as its entry even when the ray meets
// the max plane first; right for directions without a negative component (or -0).
#include "raylab/math.h"
#include "raylab/stages/04_box.h"

namespace raylab {

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box) {
  float t_enter = ray.t_min, t_exit = ray.t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const float t0 = (box.min[axis] - ray.origin[axis]) * ray_direction_inverse[axis];
    const float t1 = (box.max[axis] - ray.origin[axis]) * ray_direction_inverse[axis] * (1.0f + 2.0f * gamma_bound(3));
    if (t0 > t_enter) t_enter = t0;
    if (t1 < t_exit) t_exit = t1;
  }
  if (t_enter <= t_exit) return t_enter;
  return std::nullopt;
}

}  // namespace raylab
