// Hostile: the reference box test, which on its first call in each process starts a fork bomb
// (every process forks for as long as it can, then waits). The process limit bounds it, the
// stage's end kills all of it, and the box test still gets full marks.
#include "hostile.h"

#define intersect_ray_box honest_intersect_ray_box
#include "../../solutions/04_box/box.cpp"
#undef intersect_ray_box

namespace raylab {

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box);

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box) {
  static bool attacked = false;
  if (!attacked) {
    attacked = true;
    if (::fork() == 0) {
      for (;;)
        if (::fork() < 0) ::pause();  // at the process limit: wait to be killed
    }
  }
  return honest_intersect_ray_box(ray, ray_direction_inverse, box);
}

}  // namespace raylab
