// Grader self-test submissions of stage 03_triangle that break one rule of the contract each share
// this Moller-Trumbore test: a submission file sets the flags of its mistake and includes this file.
//   #define TRIANGLE_VARIANT(v) v.check_t_max = false
//   #include "triangle_variant.h"
// (The older triangle submissions are whole files of their own.)
#pragma once

#include "raylab/stages/03_triangle.h"

#include <glm/glm.hpp>

namespace raylab::submission {

struct TriangleVariant {
  bool check_t_max = true;             // false: hits beyond t_max accepted
  bool normalise_direction = false;    // true: t measured along the normalised direction
  bool ends_included = false;          // true: t >= t_min and t <= t_max count
  bool degenerate_hits = false;        // true: det == 0 (a parallel ray, no area) is a hit where the ray
                                       // passes nearest p0, with barycentrics (0, 0)
};

inline std::optional<TriangleHit> triangle_variant(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                   const glm::vec3& p2, const TriangleVariant& v) {
  const glm::vec3 direction = v.normalise_direction ? glm::normalize(ray.direction) : ray.direction;
  const glm::vec3 edge_01 = p1 - p0, edge_02 = p2 - p0, s = ray.origin - p0;
  const glm::vec3 s1 = glm::cross(direction, edge_02), s2 = glm::cross(s, edge_01);
  const float det = glm::dot(s1, edge_01);
  if (det == 0.0f) {
    if (!v.degenerate_hits) return std::nullopt;
    const float t = glm::dot(p0 - ray.origin, direction) / glm::dot(direction, direction);
    if (t > ray.t_min && t < ray.t_max) return TriangleHit{t, 0.0f, 0.0f};
    return std::nullopt;
  }
  const float t = glm::dot(s2, edge_02) / det;
  const float b1 = glm::dot(s1, s) / det;
  const float b2 = glm::dot(s2, direction) / det;
  if (b1 < 0.0f || b2 < 0.0f || b1 + b2 > 1.0f) return std::nullopt;
  if (v.ends_included ? !(t >= ray.t_min) : !(t > ray.t_min)) return std::nullopt;
  if (v.check_t_max && (v.ends_included ? !(t <= ray.t_max) : !(t < ray.t_max))) return std::nullopt;
  return TriangleHit{t, b1, b2};
}

}  // namespace raylab::submission

namespace raylab {
std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  static const submission::TriangleVariant variant = [] {
    submission::TriangleVariant v;
    TRIANGLE_VARIANT(v);
    return v;
  }();
  return submission::triangle_variant(ray, p0, p1, p2, variant);
}
}  // namespace raylab
