// Grader self-test submission (stage 04_box): mistake: std::max/std::min let 0 * infinity = NaN through, so a ray in a face's plane misses
#include "raylab/math.h"
#include "raylab/stages/04_box.h"

#include <algorithm>
#include <utility>

namespace raylab {

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box) {
  float t_enter = ray.t_min, t_exit = ray.t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const float t0 = (box.min[axis] - ray.origin[axis]) * ray_direction_inverse[axis];
    const float t1 = (box.max[axis] - ray.origin[axis]) * ray_direction_inverse[axis];
    t_enter = std::max(std::min(t0, t1), t_enter);  // NaN first: std::max returns it
    t_exit = std::min(std::max(t0, t1) * (1.0f + 2.0f * gamma_bound(3)), t_exit);  // Ize's conservative exit
  }
  if (t_enter <= t_exit) return t_enter;
  return std::nullopt;
}

}  // namespace raylab
