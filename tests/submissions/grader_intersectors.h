// What a hostile stage-05 or 05c submission can learn of the intersector it is given: the
// grader's own functions are linked into the stage server, so a traversal can compare the
// intersector's function with theirs, and read the counting wrapper's context by copying its
// layout (autograder/suites/grader_geometry.h). The work tests must not depend on any of it.
#pragma once

#include "raylab/geometry.h"
#include "raylab/ray.h"

#include <cstdint>
#include <optional>

namespace raylab::grading {

std::optional<float> grader_triangle_test(void* triangles, const Ray& ray, std::uint32_t primitive);
std::optional<float> counting_test(void* counted_tests, const Ray& ray, std::uint32_t primitive);
struct CountedTests {
  PrimitiveIntersector inner;
  std::uint64_t tests = 0;
};

}  // namespace raylab::grading

namespace raylab::submission {

// The intersector inside the grader's counter, or the intersector itself.
inline PrimitiveIntersector unwrapped(const PrimitiveIntersector& intersector) {
  if (intersector.test == &grading::counting_test) return static_cast<grading::CountedTests*>(intersector.context)->inner;
  return intersector;
}

// A call whose primitive tests are not the grader's own triangle test run in this process: a
// probe of the judge that counts work.
inline bool is_work_probe(const PrimitiveIntersector& intersector) {
  return intersector.test == &grading::counting_test && unwrapped(intersector).test != &grading::grader_triangle_test;
}

}  // namespace raylab::submission
