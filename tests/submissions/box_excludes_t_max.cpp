// Grader self-test submission (stage 04_box), broken: a box entered exactly at t_max is missed (a
// strict t_enter < t_max), where the contract includes both ends of [t_min, t_max]. The
// reference's slab test is included under another name, run with t_max one float lower.
#define intersect_ray_box reference_intersect_ray_box
#include "../../solutions/04_box/box.cpp"
#undef intersect_ray_box

#include <cmath>

namespace raylab {

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box);

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box) {
  Ray strict = ray;
  strict.t_max = std::nextafter(ray.t_max, 0.0f);  // the mistake: t < t_max
  return reference_intersect_ray_box(strict, ray_direction_inverse, box);
}

}  // namespace raylab
