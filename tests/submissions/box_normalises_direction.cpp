// Grader self-test submission (stage 04_box), broken: ignores ray_direction_inverse and runs the slab
// test along the normalised direction, so the t it returns, and compares with t_min and t_max, is a
// distance, not the parameter of origin + t * direction (wrong when |direction| != 1). The
// reference's slab test is included under another name, so only that differs.
#define intersect_ray_box reference_intersect_ray_box
#include "../../solutions/04_box/box.cpp"
#undef intersect_ray_box

namespace raylab {

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box);

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box) {
  (void)ray_direction_inverse;
  Ray unit = ray;
  unit.direction = glm::normalize(ray.direction);  // the mistake
  return reference_intersect_ray_box(unit, 1.0f / unit.direction, box);
}

}  // namespace raylab
