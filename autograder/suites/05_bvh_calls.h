// Stage 05's call between the judge and the stage server (05_bvh_calls.cpp) for many rays at once.
#pragma once

#include "protocol.h"
#include "stage_session.h"

#include "raylab/ray.h"
#include "raylab/stages/05_bvh.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace raylab::grading {

// intersect_bvh(bvh, ray, the grader's triangle test on `triangles`, any_hit, stats) on each ray,
// in order: the hits. In the judge, all of them in one request (the tree and the mesh are sent
// only when the stage server does not hold them already).
std::vector<std::optional<BvhHit>> intersect_bvh_each(const Bvh& bvh, const std::vector<protocol::Triangle>& triangles,
                                                      const std::vector<Ray>& rays, bool any_hit);

// One ray's traversal as stages 05, 05c and 05d send it: the judge reads back the hit, the stats the
// traversal reports and the primitive tests the server counted.
struct TraversalReply {
  std::optional<BvhHit> hit;
  std::uint64_t nodes_visited = 0, reported_tests = 0, counted_tests = 0;
};
// In the judge: the reply serve_traversal wrote.
TraversalReply read_traversal_reply(protocol::Reader& in);
// In the judge: adds the traversal's work to `stats`: with the grader's triangle test, the tests the
// server counted; with any other intersector (a work test's, which counts in the judge), what the
// traversal says, for the work test to check.
void add_traversal_work(const TraversalReply& reply, bool grader_test, BvhTraversalStats& stats);
// A traversal of one ray through a tree the stage server holds, with the intersector given.
using Traversal = std::function<std::optional<BvhHit>(const Ray& ray, const PrimitiveIntersector& intersector,
                                                      bool any_hit, BvhTraversalStats& stats)>;
// In the stage server: `traverse` on one ray with an intersector that counts its calls (the grader's
// triangle test on `triangles` with grader_test, else the judge's answers); writes the reply.
void serve_traversal(protocol::Writer& out, const Ray& ray, bool any_hit, bool grader_test,
                     std::vector<protocol::Triangle>& triangles, const Traversal& traverse);
// In the stage server: `traverse` on each ray with the grader's triangle test on `triangles`.
std::vector<std::optional<BvhHit>> traverse_each(const std::vector<protocol::Triangle>& triangles,
                                                 const std::vector<Ray>& rays, bool any_hit, const Traversal& traverse);

// A traversal's primitive tests when its intersector is not the grader's triangle test (the work
// tests' counting probes, stages 05, 05c and 05d): each test is a question to the judge.
// In the judge: the answers, `intersector` on the ray and primitive asked.
StageSession::Callback answer_primitive_tests(const PrimitiveIntersector& intersector);
// In the stage server: the intersector that asks, PrimitiveIntersector{primitive_test_through_judge, nullptr}.
std::optional<float> primitive_test_through_judge(void*, const Ray& ray, std::uint32_t primitive);

}  // namespace raylab::grading
