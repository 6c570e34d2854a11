// Stage 03_triangle: where a ray meets a triangle, with barycentric coordinates.
// Write it in assignments/03_triangle/triangle.cpp; handout: docs/03_triangle.md.
#pragma once

#include "raylab/ray.h"

#include <optional>
#include <ostream>

namespace raylab {

// A ray-triangle hit. The point is ray.at(t_hit) =
//   (1 - barycentric_b1 - barycentric_b2) * p0 + barycentric_b1 * p1 + barycentric_b2 * p2.
struct TriangleHit {
  float t_hit = 0.0f;
  float barycentric_b1 = 0.0f;  // weight of p1
  float barycentric_b2 = 0.0f;  // weight of p2
};

std::ostream& operator<<(std::ostream& out, const TriangleHit& hit);

// The hit of the ray with triangle (p0, p1, p2), from either side, if it lies in the open
// interval (ray.t_min, ray.t_max) and inside the triangle (edges included); else std::nullopt.
std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0,
                                                  const glm::vec3& p1, const glm::vec3& p2);

}  // namespace raylab
