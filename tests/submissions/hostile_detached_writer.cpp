// Hostile: the reference sphere test, which on its first call in each process leaves a
// grandchild in its own session (setsid) that writes a full-marks results.json 3 s later, after
// the grader has exited. It must be killed with its stage: full marks, and results.json unchanged.
#include "hostile.h"

#define intersect_ray_sphere honest_intersect_ray_sphere
#include "../../solutions/02_sphere/sphere.cpp"
#undef intersect_ray_sphere

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius);

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  static bool attacked = false;
  if (!attacked) {
    attacked = true;
    hostile::detach_late_writer(3);
  }
  return honest_intersect_ray_sphere(ray, sphere_center, sphere_radius);
}

}  // namespace raylab
