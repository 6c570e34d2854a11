// Grader self-test submission (stage 03_triangle): mistake: one strict comparison, b1 > 0, so
// points on the edge p0-p2 (b1 = 0) are missed; every other point right. The contract counts
// edges and corners as inside.
#include "raylab/stages/03_triangle.h"

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  const glm::vec3 edge_01 = p1 - p0, edge_02 = p2 - p0, s = ray.origin - p0;
  const glm::vec3 s1 = glm::cross(ray.direction, edge_02), s2 = glm::cross(s, edge_01);
  const float det = glm::dot(s1, edge_01);
  if (det == 0.0f) return std::nullopt;
  const float t_hit = glm::dot(s2, edge_02) / det;
  const float b1 = glm::dot(s1, s) / det;
  const float b2 = glm::dot(s2, ray.direction) / det;
  if (!(b1 > 0) || !(b2 >= 0) || !(b1 + b2 <= 1) || !(t_hit > ray.t_min && t_hit < ray.t_max)) return std::nullopt;
  return TriangleHit{t_hit, b1, b2};
}

}  // namespace raylab
