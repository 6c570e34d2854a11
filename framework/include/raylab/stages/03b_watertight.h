// Stage 03b_watertight (bonus): a ray-triangle test that never lets a ray slip between two
// triangles sharing an edge (Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection",
// JCGT 2013). Write it in assignments/03b_watertight/watertight.cpp (its comment is the full
// contract); handout: docs/03b_watertight.md. Graded by the bonus stage 06_robustness.
#pragma once

#include "raylab/ray.h"
#include "raylab/stages/03_triangle.h"

#include <optional>

namespace raylab {

// The same contract as intersect_ray_triangle (stage 03): the hit of the ray with triangle
// (p0, p1, p2), from either side, with ray.t_min < t_hit < ray.t_max, inside the triangle
// (edges included), barycentric_b1 = weight of p1, barycentric_b2 = weight of p2; else
// std::nullopt. In addition: a ray through a closed mesh hits at least one of the triangles
// around every shared edge and vertex it passes through (no leaks), and degenerate triangles
// or rays parallel to the plane give no hit (never NaN).
std::optional<TriangleHit> intersect_ray_triangle_watertight(const Ray& ray, const glm::vec3& p0,
                                                             const glm::vec3& p1, const glm::vec3& p2);

}  // namespace raylab
