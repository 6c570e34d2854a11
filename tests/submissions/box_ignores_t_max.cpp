// Grader self-test submission (stage 04_box): mistake: t_exit starts at infinity instead of t_max
#include "raylab/math.h"
#include "raylab/stages/04_box.h"

#include <algorithm>
#include <utility>

namespace raylab {

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box) {
  float t_enter = ray.t_min, t_exit = kInfinity;
  for (int axis = 0; axis < 3; ++axis) {
    float t0 = (box.min[axis] - ray.origin[axis]) * ray_direction_inverse[axis];
    float t1 = (box.max[axis] - ray.origin[axis]) * ray_direction_inverse[axis];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_enter) t_enter = t0;
    t1 *= 1.0f + 2.0f * gamma_bound(3);  // Ize's conservative exit (docs/04_box.md, section 4)
    if (t1 < t_exit) t_exit = t1;
  }
  if (t_enter <= t_exit) return t_enter;
  return std::nullopt;
}

}  // namespace raylab
