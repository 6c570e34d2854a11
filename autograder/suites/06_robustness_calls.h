// Stage 06's batch calls (06_robustness_calls.cpp): the watertight triangle test on many inputs,
// and the leak test's rays against a closed mesh.
#pragma once

#include "protocol.h"

#include "raylab/ray.h"
#include "raylab/testkit/triangles.h"

#include <cstdint>
#include <optional>
#include <tuple>
#include <vector>

namespace raylab::grading {

// intersect_ray_triangle_watertight(ray, p0, p1, p2) on each set of arguments, in order; in the
// judge, all of them in one request (stage_call.h, call_remote_each).
using TriangleTestArguments = std::tuple<Ray, glm::vec3, glm::vec3, glm::vec3>;
std::vector<std::optional<TriangleHit>> intersect_ray_triangle_watertight_each(
    const std::vector<TriangleTestArguments>& calls);

using testkit::TriangleFunction;  // intersect_ray_triangle or intersect_ray_triangle_watertight

// For each ray i, the triangles (indices into `triangles`) among candidates[i] that
// function(ray, p0, p1, p2) reports a hit for; every triangle is a candidate when `candidates` is
// empty. function is intersect_ray_triangle or intersect_ray_triangle_watertight.
std::vector<std::vector<std::uint32_t>> triangles_hit(TriangleFunction function,
                                                      const std::vector<protocol::Triangle>& triangles,
                                                      const std::vector<Ray>& rays,
                                                      const std::vector<std::vector<std::uint32_t>>& candidates);

}  // namespace raylab::grading
