// Stage 06's batch call (06_robustness_calls.cpp): the leak test's rays against a closed mesh.
#pragma once

#include "protocol.h"

#include "raylab/ray.h"
#include "raylab/testkit/triangles.h"

#include <cstdint>
#include <vector>

namespace raylab::grading {

using testkit::TriangleFunction;  // intersect_ray_triangle or intersect_ray_triangle_watertight

// For each ray i, the triangles (indices into `triangles`) among candidates[i] that
// function(ray, p0, p1, p2) reports a hit for; every triangle is a candidate when `candidates` is
// empty. function is intersect_ray_triangle or intersect_ray_triangle_watertight.
std::vector<std::vector<std::uint32_t>> triangles_hit(TriangleFunction function,
                                                      const std::vector<protocol::Triangle>& triangles,
                                                      const std::vector<Ray>& rays,
                                                      const std::vector<std::vector<std::uint32_t>>& candidates);

}  // namespace raylab::grading
