// Grader self-test submission (stage 03b_watertight): the reference watertight test without
// the t error bound (delta_t). No leaks, the same answers as stage 03; but a ray leaving a
// large triangle can hit it again at a tiny t: shadow acne, which 06_robustness must see.
#include "raylab/stages/03b_watertight.h"

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

  // MISTAKE: no bound on the rounding error of t: a hit at a tiny t may be the ray's own surface
  return TriangleHit{t_hit, v * inverse_determinant, w * inverse_determinant};
}

}  // namespace raylab
