// Reference solution, stage 03b_watertight (Woop, Benthin and Wald 2013). The contract is in
// assignments/03b_watertight/watertight.cpp and docs/03b_watertight.md.
#include "raylab/stages/03b_watertight.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace raylab {
namespace {

inline int largest_axis(const glm::vec3& v) {
  const glm::vec3 a = glm::abs(v);
  if (a.x >= a.y && a.x >= a.z) return 0;
  return a.y >= a.z ? 1 : 2;
}

// A corner in the ray's space: the ray runs along +z through (0, 0).
struct Sheared {
  float x, y, z;
};

}  // namespace

std::optional<TriangleHit> intersect_ray_triangle_watertight(const Ray& ray, const glm::vec3& p0,
                                                             const glm::vec3& p1, const glm::vec3& p2) {
  const glm::vec3& d = ray.direction;
  const int kz = largest_axis(d);
  if (!(d[kz] != 0.0f) || !std::isfinite(d[kz])) return std::nullopt;  // zero or NaN direction
  const int kx = (kz + 1) % 3;
  const int ky = (kx + 1) % 3;
  const float shear_x = -d[kx] / d[kz];
  const float shear_y = -d[ky] / d[kz];
  const float shear_z = 1.0f / d[kz];

  // Each corner depends on the ray and that corner only: a corner shared by two triangles is
  // transformed to exactly the same floats in both, and so is every shared edge's test.
  auto shear = [&](const glm::vec3& p) {
    const glm::vec3 a = p - ray.origin;
    return Sheared{a[kx] + shear_x * a[kz], a[ky] + shear_y * a[kz], shear_z * a[kz]};
  };
  const Sheared s0 = shear(p0), s1 = shear(p1), s2 = shear(p2);

  // Edge functions: twice the signed area of the ray's point with each edge, in 2D.
  float u = s2.x * s1.y - s2.y * s1.x;  // edge p1-p2: weight of p0
  float v = s0.x * s2.y - s0.y * s2.x;  // edge p2-p0: weight of p1
  float w = s1.x * s0.y - s1.y * s0.x;  // edge p0-p1: weight of p2
  if (u == 0.0f || v == 0.0f || w == 0.0f) {
    // Exactly on an edge in float, or a tiny area rounded to 0: the products of two floats are
    // exact in double, so the signs there are the true ones.
    u = static_cast<float>(double(s2.x) * double(s1.y) - double(s2.y) * double(s1.x));
    v = static_cast<float>(double(s0.x) * double(s2.y) - double(s0.y) * double(s2.x));
    w = static_cast<float>(double(s1.x) * double(s0.y) - double(s1.y) * double(s0.x));
  }
  // Outside when the signs differ (zeros are on an edge: inside). NaN fails both: a miss below.
  if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return std::nullopt;
  const float determinant = u + v + w;
  if (!(determinant != 0.0f) || !std::isfinite(determinant)) return std::nullopt;

  const float inverse_determinant = 1.0f / determinant;
  const float t_hit = (u * s0.z + v * s1.z + w * s2.z) * inverse_determinant;
  if (!(t_hit > ray.t_min && t_hit < ray.t_max)) return std::nullopt;

  // t itself carries rounding error; a hit closer than that bound may be the ray's own
  // surface (a shadow ray leaving a large triangle). pbrt-v4 (Triangle::Intersect) bounds it
  // from the sheared z values, x and y values and edge functions, each with its gamma term.
  const float max_z = std::max({std::fabs(s0.z), std::fabs(s1.z), std::fabs(s2.z)});
  const float max_x = std::max({std::fabs(s0.x), std::fabs(s1.x), std::fabs(s2.x)});
  const float max_y = std::max({std::fabs(s0.y), std::fabs(s1.y), std::fabs(s2.y)});
  const float delta_z = gamma_bound(3) * max_z;
  const float delta_x = gamma_bound(5) * (max_x + max_z);
  const float delta_y = gamma_bound(5) * (max_y + max_z);
  const float delta_e = 2.0f * (gamma_bound(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
  const float max_e = std::max({std::fabs(u), std::fabs(v), std::fabs(w)});
  const float delta_t =
      3.0f * (gamma_bound(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * std::fabs(inverse_determinant);
  if (!(t_hit > delta_t)) return std::nullopt;
  return TriangleHit{t_hit, v * inverse_determinant, w * inverse_determinant};
}

}  // namespace raylab
