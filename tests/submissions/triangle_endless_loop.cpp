// Grader self-test submission (stage 03_triangle): never returns (an endless loop)
#include "raylab/stages/03_triangle.h"

#include <cmath>

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  (void)ray; (void)p0; (void)p1; (void)p2;
  for (volatile unsigned spin = 0;; spin = spin + 1) {
  }
}

}  // namespace raylab
