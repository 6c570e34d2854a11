#include "raylab/testkit/oracles.h"

#include <cmath>
#include <utility>

namespace raylab::testkit {

std::optional<SphereRoots> exact_sphere_roots(const Ray& ray, const glm::vec3& center, float radius,
                                              long double* margin) {
  using L = long double;
  // Differences and products of floats are exact or nearly so in long double's 64 bits.
  const L o[3] = {L(ray.origin.x) - L(center.x), L(ray.origin.y) - L(center.y), L(ray.origin.z) - L(center.z)};
  const L d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  const L a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const L r2 = L(radius) * L(radius);
  if (margin) *margin = 0;
  if (!(a > 0)) return std::nullopt;
  const L half_b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
  const L c = (o[0] * o[0] + o[1] * o[1] + o[2] * o[2]) - r2;
  // discriminant / (4a) = r^2 - (squared distance from the centre to the line)
  L perp2 = 0;
  for (int i = 0; i < 3; ++i) {
    const L p = o[i] - half_b / a * d[i];
    perp2 += p * p;
  }
  const L reduced = r2 - perp2;
  if (margin) *margin = std::fabs(reduced) / r2;
  if (reduced < 0) return std::nullopt;
  const L root = std::sqrt(a * reduced);
  const L q = half_b < 0 ? -(half_b - root) : -(half_b + root);
  SphereRoots roots;
  roots.t0 = q / a;
  roots.t1 = q != 0 ? c / q : roots.t0;  // q == 0: a double root at t = 0 (c / q is 0 / 0)
  if (roots.t0 > roots.t1) std::swap(roots.t0, roots.t1);
  return roots;
}

std::optional<long double> exact_sphere_hit(const Ray& ray, const glm::vec3& center, float radius,
                                            long double* margin) {
  const std::optional<SphereRoots> roots = exact_sphere_roots(ray, center, radius, margin);
  if (!roots) return std::nullopt;
  for (const long double t : {roots->t0, roots->t1})
    if (t > ray.t_min && t < ray.t_max) return t;
  return std::nullopt;
}

}  // namespace raylab::testkit
