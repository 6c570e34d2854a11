// The reference cases of stage 06_robustness: spheres that the textbook quadratic gets wrong, with exact answers.
// autograder-regenerate writes them to autograder/reference/06_robustness_cases.json with the answers
// of the solutions it is linked with; the suite (06_robustness_test.cpp) grades against them.
#include "support.h"

#include "raylab/math.h"
#include "raylab/ray.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace raylab::grading {
namespace {

using nlohmann::json;

// Stage 06_robustness: spheres that the textbook quadratic gets wrong, with the EXACT answer
// for the float inputs (long double), not the reference's float one. Two kinds:
//   far_tiny   spheres 100 to 100,000 away, radius 1e-4 to 1e-2 of that (b^2 - 4ac cancels)
//   huge_near  integer spheres of radius 500 to 4000 seen from within a few units of their
//              surface, where c = |oc|^2 - R^2 is exact in float but -b - sqrt(disc) cancels
std::optional<long double> exact_sphere_hit(const Ray& ray, const glm::vec3& center, float radius, long double* margin) {
  using L = long double;
  L o[3], d[3];
  for (int i = 0; i < 3; ++i) o[i] = L(ray.origin[i]) - L(center[i]), d[i] = ray.direction[i];
  const L a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const L half_b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
  const L r2 = L(radius) * L(radius);
  const L c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - r2;
  L perp2 = 0;
  for (int i = 0; i < 3; ++i) perp2 += (o[i] - half_b / a * d[i]) * (o[i] - half_b / a * d[i]);
  *margin = std::fabs(r2 - perp2) / r2;
  if (r2 - perp2 < 0) return std::nullopt;
  const L root = std::sqrt(a * (r2 - perp2));
  const L q = half_b < 0 ? -(half_b - root) : -(half_b + root);
  L t0 = q / a, t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > ray.t_min && t0 < ray.t_max) return t0;
  if (t1 > ray.t_min && t1 < ray.t_max) return t1;
  return std::nullopt;
}

json robustness_cases(std::uint32_t seed, int count) {
  CaseRandom random(seed);
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    const bool far_tiny = cases.size() % 2 == 0;
    Ray ray;
    glm::vec3 center;
    float radius;
    if (far_tiny) {
      const float distance = std::exp(random.uniform(std::log(1e2f), std::log(1e5f)));
      const glm::vec3 axis = glm::normalize(random.vec3(-1, 1));
      center = distance * axis;
      radius = distance * std::exp(random.uniform(std::log(1e-4f), std::log(1e-2f)));
      ray.origin = random.vec3(-1, 1);
      const glm::vec3 target = center + random.uniform(0, 1.1f) * radius * glm::normalize(random.vec3(-1, 1));
      ray.direction = glm::normalize(target - ray.origin) * random.uniform(0.5f, 2.0f);
    } else {
      // Looking along an axis at an integer sphere whose centre is `offset` to the side:
      // the near surface is about offset^2 / (2 radius) away.
      radius = static_cast<float>(random.integer(500, 4000));
      const int axis = random.integer(0, 2), side = (axis + 1 + random.integer(0, 1)) % 3;
      const float sign = random.integer(0, 1) ? 1.0f : -1.0f;
      center = glm::vec3(static_cast<float>(random.integer(-50, 50)), static_cast<float>(random.integer(-50, 50)),
                         static_cast<float>(random.integer(-50, 50)));
      ray.origin = center;
      ray.origin[axis] -= sign * radius;
      ray.origin[side] += static_cast<float>(random.integer(1, 30));
      ray.direction = glm::vec3(0.0f);
      ray.direction[axis] = sign * static_cast<float>(1 << random.integer(0, 3));
    }
    if (!is_finite(ray.direction) || glm::length(ray.direction) == 0.0f) continue;
    long double margin = 0;
    const std::optional<long double> t = exact_sphere_hit(ray, center, radius, &margin);
    if (margin < 1e-3L) continue;  // near-tangent: a correct float kernel may go either way
    cases.push_back({{"id", cases.size()}, {"kind", far_tiny ? "far_tiny" : "huge_near"}, {"origin", to_json(ray.origin)},
                     {"direction", to_json(ray.direction)}, {"center", to_json(center)}, {"radius", radius},
                     {"t_exact", t ? json(static_cast<double>(*t)) : json(nullptr)}});
  }
  return cases;
}

const bool kRegistered =
    register_reference_data("06_robustness", {[](std::uint32_t seed) { return json{{"cases", robustness_cases(seed, 400)}}; }});

}  // namespace
}  // namespace raylab::grading
