// Grader self-test submissions of stage 03b_watertight (graded at 06_robustness) that break one rule
// of the contract each share this file: the reference's watertight test under another name, and a
// wrapper that sets the flags of one mistake.
//   #define WATERTIGHT_VARIANT(v) v.check_t_max = false
//   #include "watertight_variant.h"
#pragma once

#include "raylab/stages/03b_watertight.h"

#define intersect_ray_triangle_watertight reference_intersect_ray_triangle_watertight
#include "../../solutions/03b_watertight/watertight.cpp"
#undef intersect_ray_triangle_watertight

#include <glm/glm.hpp>

#include <limits>
#include <utility>

namespace raylab::submission {

struct WatertightVariant {
  bool normalise_direction = false;   // t measured along the normalised direction
  bool check_t_max = true;            // false: hits beyond t_max accepted
  bool cull_back_faces = false;       // a triangle seen from its back (by its winding) is missed
  bool swap_barycentrics = false;     // b1 and b2 exchanged
  bool degenerate_gives_nan = false;  // a triangle without area divides by its zero determinant: NaN
  bool degenerate_hits = false;       // a triangle without area, or one the ray runs parallel to, is hit where the
                                      // ray passes nearest its first corner
};

}  // namespace raylab::submission

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle_watertight(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                             const glm::vec3& p2);

std::optional<TriangleHit> intersect_ray_triangle_watertight(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                             const glm::vec3& p2) {
  static const submission::WatertightVariant v = [] {
    submission::WatertightVariant flags;
    WATERTIGHT_VARIANT(flags);
    return flags;
  }();
  const glm::vec3 normal = glm::cross(p1 - p0, p2 - p0);
  if (v.degenerate_gives_nan && normal == glm::vec3(0.0f)) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    return TriangleHit{nan, nan, nan};
  }
  if (v.degenerate_hits && (normal == glm::vec3(0.0f) || glm::dot(normal, ray.direction) == 0.0f)) {
    const float t = glm::dot(p0 - ray.origin, ray.direction) / glm::dot(ray.direction, ray.direction);
    if (t > ray.t_min && t < ray.t_max) return TriangleHit{t, 0.0f, 0.0f};
  }
  if (v.cull_back_faces && glm::dot(normal, ray.direction) > 0.0f) return std::nullopt;
  Ray changed = ray;
  if (v.normalise_direction) changed.direction = glm::normalize(ray.direction);
  if (!v.check_t_max) changed.t_max = std::numeric_limits<float>::infinity();
  std::optional<TriangleHit> hit = reference_intersect_ray_triangle_watertight(changed, p0, p1, p2);
  if (hit && v.swap_barycentrics) std::swap(hit->barycentric_b1, hit->barycentric_b2);
  return hit;
}

}  // namespace raylab
