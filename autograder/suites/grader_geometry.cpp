// The grader's own geometry (grader_geometry.h): a triangle test shared by the judge's brute-force
// oracle and the stage server's BVH traversal requests, so both see exactly the same hits; and
// the camera rays, sphere and triangle tests that stages 08 and 09 trace their scenes with, so
// that a mistake in stages 01-05 costs points in its own stage only: the testkit's exact ones
// (raylab/testkit/exact_tracing.h), which `raylab trace` also holds your calls against.
#include "grader_geometry.h"

#include "raylab/testkit/exact_tracing.h"

namespace raylab::grading {

std::optional<float> grader_triangle_test(void* triangles, const Ray& ray, std::uint32_t primitive) {
  const protocol::Triangle& triangle = static_cast<const std::vector<protocol::Triangle>*>(triangles)->at(primitive);
  const std::optional<TriangleHit> hit = testkit::exact_triangle_test(ray, triangle[0], triangle[1], triangle[2]);
  return hit ? std::optional<float>(hit->t_hit) : std::nullopt;
}

std::optional<float> counting_test(void* counted_tests, const Ray& ray, std::uint32_t primitive) {
  auto* counted = static_cast<CountedTests*>(counted_tests);
  ++counted->tests;
  return counted->inner.test(counted->inner.context, ray, primitive);
}

TracingFunctions grader_tracing() { return testkit::exact_tracing(); }

}  // namespace raylab::grading
