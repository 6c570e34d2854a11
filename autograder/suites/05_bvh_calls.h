// Stage 05's call between the judge and the stage server (05_bvh_calls.cpp) for many rays at once.
#pragma once

#include "protocol.h"
#include "stage_session.h"

#include "raylab/ray.h"
#include "raylab/stages/05_bvh.h"

#include <optional>
#include <vector>

namespace raylab::grading {

// intersect_bvh(bvh, ray, the grader's triangle test on `triangles`, any_hit, stats) on each ray,
// in order: the hits. In the judge, all of them in one request (the tree and the mesh are sent
// only when the stage server does not hold them already).
std::vector<std::optional<BvhHit>> intersect_bvh_each(const Bvh& bvh, const std::vector<protocol::Triangle>& triangles,
                                                      const std::vector<Ray>& rays, bool any_hit);

// A traversal's primitive tests when its intersector is not the grader's triangle test (the work
// tests' counting probes, stages 05 and 05c): each test is a question to the judge.
// In the judge: the answers, `intersector` on the ray and primitive asked.
StageSession::Callback answer_primitive_tests(const PrimitiveIntersector& intersector);
// In the stage server: the intersector that asks, PrimitiveIntersector{primitive_test_through_judge, nullptr}.
std::optional<float> primitive_test_through_judge(void*, const Ray& ray, std::uint32_t primitive);

}  // namespace raylab::grading
