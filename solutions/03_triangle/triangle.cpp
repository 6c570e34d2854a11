// Reference solution, stage 03_triangle (Moller-Trumbore). The contract is in
// assignments/03_triangle/triangle.cpp and docs/03_triangle.md.
#include "raylab/stages/03_triangle.h"

#include <cmath>

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0,
                                                  const glm::vec3& p1, const glm::vec3& p2) {
  // Solve origin + t d = p0 + b1 (p1 - p0) + b2 (p2 - p0) with Cramer's rule, written with
  // cross products that are shared between the three unknowns.
  const glm::vec3 edge_01 = p1 - p0;
  const glm::vec3 edge_02 = p2 - p0;
  const glm::vec3 direction_cross_edge_02 = glm::cross(ray.direction, edge_02);
  const float determinant = glm::dot(edge_01, direction_cross_edge_02);
  // Zero: the ray is parallel to the plane, or the triangle has no area. (NaN fails too.)
  if (!(determinant != 0.0f) || !std::isfinite(determinant)) return std::nullopt;
  const float inverse_determinant = 1.0f / determinant;

  const glm::vec3 p0_to_origin = ray.origin - p0;
  const float barycentric_b1 = glm::dot(p0_to_origin, direction_cross_edge_02) * inverse_determinant;
  if (!(barycentric_b1 >= 0.0f && barycentric_b1 <= 1.0f)) return std::nullopt;

  const glm::vec3 origin_cross_edge_01 = glm::cross(p0_to_origin, edge_01);
  const float barycentric_b2 = glm::dot(ray.direction, origin_cross_edge_01) * inverse_determinant;
  if (!(barycentric_b2 >= 0.0f && barycentric_b1 + barycentric_b2 <= 1.0f)) return std::nullopt;

  const float t_hit = glm::dot(edge_02, origin_cross_edge_01) * inverse_determinant;
  if (!(t_hit > ray.t_min && t_hit < ray.t_max)) return std::nullopt;
  return TriangleHit{t_hit, barycentric_b1, barycentric_b2};
}

}  // namespace raylab
