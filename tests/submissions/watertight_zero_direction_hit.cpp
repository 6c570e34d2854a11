// Grader self-test submission (stage 03b_watertight, graded at 06_robustness), broken: the
// watertight test written with "reject when" checks (det == 0, t <= t_min, t >= t_max), as many
// texts write it, and no check of the direction. A zero direction shears by 1 / 0: every edge
// function and t is NaN, every "reject when" comparison is false, and a hit at t = NaN comes back.
// It rejects an infinite determinant, so every other input is answered as the reference answers it
// (its t error bound, its exact signs on an edge) but the NaN corner, which the same NaN reaches.
// Only the test of degenerate inputs fails, with its hint.
#include "raylab/math.h"
#include "raylab/stages/03b_watertight.h"

#include <algorithm>
#include <cmath>

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle_watertight(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                             const glm::vec3& p2) {
  const glm::vec3& d = ray.direction;
  const glm::vec3 a = glm::abs(d);
  const int kz = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
  const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  const float sx = -d[kx] / d[kz], sy = -d[ky] / d[kz], sz = 1.0f / d[kz];
  glm::vec3 s[3];
  const glm::vec3* corners[3] = {&p0, &p1, &p2};
  for (int i = 0; i < 3; ++i) {
    const glm::vec3 q = *corners[i] - ray.origin;
    s[i] = glm::vec3(q[kx] + sx * q[kz], q[ky] + sy * q[kz], sz * q[kz]);
  }
  float u = s[2].x * s[1].y - s[2].y * s[1].x;
  float v = s[0].x * s[2].y - s[0].y * s[2].x;
  float w = s[1].x * s[0].y - s[1].y * s[0].x;
  if (u == 0.0f || v == 0.0f || w == 0.0f) {
    u = static_cast<float>(double(s[2].x) * double(s[1].y) - double(s[2].y) * double(s[1].x));
    v = static_cast<float>(double(s[0].x) * double(s[2].y) - double(s[0].y) * double(s[2].x));
    w = static_cast<float>(double(s[1].x) * double(s[0].y) - double(s[1].y) * double(s[0].x));
  }
  if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return std::nullopt;
  const float det = u + v + w;
  if (det == 0.0f || std::isinf(det)) return std::nullopt;
  const float inverse = 1.0f / det;
  const float t = (u * s[0].z + v * s[1].z + w * s[2].z) * inverse;
  if (t <= ray.t_min || t >= ray.t_max) return std::nullopt;
  // The bound on t's rounding error (pbrt-v4's), as the reference computes it.
  const float max_z = std::max({std::fabs(s[0].z), std::fabs(s[1].z), std::fabs(s[2].z)});
  const float max_x = std::max({std::fabs(s[0].x), std::fabs(s[1].x), std::fabs(s[2].x)});
  const float max_y = std::max({std::fabs(s[0].y), std::fabs(s[1].y), std::fabs(s[2].y)});
  const float delta_z = gamma_bound(3) * max_z;
  const float delta_x = gamma_bound(5) * (max_x + max_z);
  const float delta_y = gamma_bound(5) * (max_y + max_z);
  const float delta_e = 2.0f * (gamma_bound(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
  const float max_e = std::max({std::fabs(u), std::fabs(v), std::fabs(w)});
  const float delta_t = 3.0f * (gamma_bound(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * std::fabs(inverse);
  if (t <= delta_t) return std::nullopt;
  return TriangleHit{t, v * inverse, w * inverse};
}

}  // namespace raylab
