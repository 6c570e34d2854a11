// Grader self-test submission (stage 03_triangle): CORRECT, but Cramer's rule on the 3x3 system with determinants, in double
#include "raylab/stages/03_triangle.h"

#include <cmath>

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  // origin + t d = p0 + b1 (p1 - p0) + b2 (p2 - p0)  <=>  [-d, e1, e2] (t, b1, b2)^T = origin - p0
  const glm::dvec3 column_0 = -glm::dvec3(ray.direction), e1 = glm::dvec3(p1) - glm::dvec3(p0),
                   e2 = glm::dvec3(p2) - glm::dvec3(p0), rhs = glm::dvec3(ray.origin) - glm::dvec3(p0);
  const double det = glm::determinant(glm::dmat3(column_0, e1, e2));
  if (det == 0.0) return std::nullopt;
  const double t = glm::determinant(glm::dmat3(rhs, e1, e2)) / det;
  const double b1 = glm::determinant(glm::dmat3(column_0, rhs, e2)) / det;
  const double b2 = glm::determinant(glm::dmat3(column_0, e1, rhs)) / det;
  if (b1 < 0 || b2 < 0 || b1 + b2 > 1) return std::nullopt;
  const float t_hit = static_cast<float>(t);
  if (!(t_hit > ray.t_min && t_hit < ray.t_max)) return std::nullopt;
  return TriangleHit{t_hit, static_cast<float>(b1), static_cast<float>(b2)};
}

}  // namespace raylab
