// The grader's own triangle test (stage_calls.h), shared by the judge's brute-force oracle and
// the stage server's BVH traversal requests, so both see exactly the same hits.
#include "stage_calls.h"

#include <cmath>

namespace raylab::grading {

std::optional<float> grader_triangle_test(void* triangles, const Ray& ray, std::uint32_t primitive) {
  const protocol::Triangle& triangle = static_cast<const std::vector<protocol::Triangle>*>(triangles)->at(primitive);
  // Cramer's rule in double: [-d, e1, e2] (t, b1, b2)^T = o - p0.
  const glm::dvec3 p0(triangle[0]), e1 = glm::dvec3(triangle[1]) - p0, e2 = glm::dvec3(triangle[2]) - p0;
  const glm::dvec3 minus_d = -glm::dvec3(ray.direction), rhs = glm::dvec3(ray.origin) - p0;
  const double det = glm::determinant(glm::dmat3(minus_d, e1, e2));
  if (det == 0.0 || !std::isfinite(det)) return std::nullopt;
  const double b1 = glm::determinant(glm::dmat3(minus_d, rhs, e2)) / det;
  const double b2 = glm::determinant(glm::dmat3(minus_d, e1, rhs)) / det;
  if (!(b1 >= 0 && b2 >= 0 && b1 + b2 <= 1)) return std::nullopt;
  const float t = static_cast<float>(glm::determinant(glm::dmat3(rhs, e1, e2)) / det);
  if (!(t > ray.t_min && t < ray.t_max)) return std::nullopt;
  return t;
}

}  // namespace raylab::grading
