// The reference's Moller-Trumbore test (stage 03_triangle) as an inline function over a
// triangle given by its first vertex and its two edges from it. solutions/03_triangle/
// triangle.cpp wraps it as the stage function; the reference's own trees over a scene's
// triangles (solutions/05_bvh/leaf_test.h) run it on the triangles in leaf order
// (TriangleEdges) instead of a call per triangle. Both run the same
// source on the same edges (p1 - p0 and p2 - p0 round the same whether computed here or
// once by the tree), so both give the same bits. Not part of any student contract.
#pragma once

#include "raylab/stages/03_triangle.h"

#include <cmath>

namespace raylab::reference {

// true and `hit` filled when the ray meets the triangle p0 + b1 edge_01 + b2 edge_02 (edges
// included) at a t in (ray.t_min, ray.t_max).
inline bool moller_trumbore(const Ray& ray, const glm::vec3& p0, const glm::vec3& edge_01,
                            const glm::vec3& edge_02, TriangleHit& hit) {
  // Solve origin + t d = p0 + b1 edge_01 + b2 edge_02 with Cramer's rule, written with cross
  // products that are shared between the three unknowns.
  const glm::vec3 direction_cross_edge_02 = glm::cross(ray.direction, edge_02);
  const float determinant = glm::dot(edge_01, direction_cross_edge_02);
  // Zero: the ray is parallel to the plane, or the triangle has no area. (NaN fails too.)
  if (!(determinant != 0.0f) || !std::isfinite(determinant)) return false;
  const float inverse_determinant = 1.0f / determinant;

  const glm::vec3 p0_to_origin = ray.origin - p0;
  const float barycentric_b1 = glm::dot(p0_to_origin, direction_cross_edge_02) * inverse_determinant;
  if (!(barycentric_b1 >= 0.0f && barycentric_b1 <= 1.0f)) return false;

  const glm::vec3 origin_cross_edge_01 = glm::cross(p0_to_origin, edge_01);
  const float barycentric_b2 = glm::dot(ray.direction, origin_cross_edge_01) * inverse_determinant;
  if (!(barycentric_b2 >= 0.0f && barycentric_b1 + barycentric_b2 <= 1.0f)) return false;

  const float t_hit = glm::dot(edge_02, origin_cross_edge_01) * inverse_determinant;
  if (!(t_hit > ray.t_min && t_hit < ray.t_max)) return false;
  hit = TriangleHit{t_hit, barycentric_b1, barycentric_b2};
  return true;
}

}  // namespace raylab::reference
