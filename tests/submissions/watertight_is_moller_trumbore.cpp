// Grader self-test submission (stage 03b_watertight): plain Moller-Trumbore offered as the
// watertight test. Right answers everywhere except that rays slip through shared edges and
// vertices of closed meshes (bonus stage 06_robustness must see the leaks).
#include "raylab/stages/03b_watertight.h"

#include <cmath>

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle_watertight(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                             const glm::vec3& p2) {
  const glm::vec3 edge_01 = p1 - p0, edge_02 = p2 - p0;
  const glm::vec3 s1 = glm::cross(ray.direction, edge_02);
  const float det = glm::dot(s1, edge_01);
  if (!(det != 0.0f) || !std::isfinite(det)) return std::nullopt;
  const glm::vec3 s = ray.origin - p0;
  const float b1 = glm::dot(s1, s) / det;
  if (!(b1 >= 0.0f && b1 <= 1.0f)) return std::nullopt;
  const glm::vec3 s2 = glm::cross(s, edge_01);
  const float b2 = glm::dot(s2, ray.direction) / det;
  if (!(b2 >= 0.0f && b1 + b2 <= 1.0f)) return std::nullopt;
  const float t = glm::dot(s2, edge_02) / det;
  if (!(t > ray.t_min && t < ray.t_max)) return std::nullopt;
  return TriangleHit{t, b1, b2};
}

}  // namespace raylab
