// The grader's own geometry (grader_geometry.cpp), linked into the judge and the stage server
// alike, in double precision with the conventions of stages 01-03 (their headers).
#pragma once

#include "protocol.h"

#include "raylab/geometry.h"
#include "raylab/ray.h"

#include <cstdint>
#include <optional>

namespace raylab::grading {

// The grader's own triangle test (Cramer's rule in double), as a PrimitiveIntersector test over
// `triangles` (a const std::vector<protocol::Triangle>*), so that BVH grades do not depend on
// your stage 3.
std::optional<float> grader_triangle_test(void* triangles, const Ray& ray, std::uint32_t primitive);

// An intersector that counts its own calls, so that a traversal's work is what the server
// counted, not what the traversal says it did: PrimitiveIntersector{counting_test, &counted}.
struct CountedTests {
  PrimitiveIntersector inner;
  std::uint64_t tests = 0;
};
std::optional<float> counting_test(void* counted_tests, const Ray& ray, std::uint32_t primitive);

// The grader's own camera rays, sphere and triangle tests (testkit::exact_tracing: in double, with
// stages 01-03's conventions), which the later stages' pictures and scenes are traced with: so
// their grades do not depend on your stages 01-05.
TracingFunctions grader_tracing();

}  // namespace raylab::grading
