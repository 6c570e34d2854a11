// Reference solution, stage 04_box (the slab test). The contract is in
// assignments/04_box/box.cpp and docs/04_box.md.
#include "raylab/stages/04_box.h"

#include "box_slabs.h"

namespace raylab {

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse,
                                       const Bounds3& box) {
  float t_enter;
  if (reference::ray_enters_box(ray.origin, ray_direction_inverse, box, ray.t_min, ray.t_max, t_enter))
    return t_enter;
  return std::nullopt;
}

}  // namespace raylab
