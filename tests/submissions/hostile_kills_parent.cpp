// Hostile: the reference triangle test, which on its first call in each process tries to kill
// the grader (its parent). The grader must survive and give full marks.
#include "hostile.h"

#define intersect_ray_triangle honest_intersect_ray_triangle
#include "../../solutions/03_triangle/triangle.cpp"
#undef intersect_ray_triangle

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2);

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  static bool attacked = false;
  if (!attacked) {
    attacked = true;
    ::kill(::getppid(), SIGTERM);
    ::kill(::getppid(), SIGKILL);
  }
  return honest_intersect_ray_triangle(ray, p0, p1, p2);
}

}  // namespace raylab
