// The reference cases of stage 06_robustness: spheres that the textbook quadratic gets wrong,
// with exact answers. autograder-regenerate writes them to
// autograder/reference/06_robustness_cases.json; the suite (06_robustness_test.cpp) grades
// against them.
#include "support.h"

#include "raylab/math.h"
#include "raylab/ray.h"
#include "raylab/testkit/oracles.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace raylab::grading {
namespace {

using nlohmann::json;

// Spheres that the textbook quadratic gets wrong, with the EXACT answer for the float inputs
// (testkit::exact_sphere_hit, in long double), not the reference's float one. Two kinds:
//   far_tiny   spheres 100 to 100,000 away, radius 1e-4 to 1e-2 of that (b^2 - 4ac cancels)
//   huge_near  integer spheres of radius 500 to 4000 seen from within a few units of their
//              surface, where c = |oc|^2 - R^2 is exact in float but -b - sqrt(disc) cancels
json robustness_cases(std::uint32_t seed, int count) {
  Pcg32 random(seed, testkit::stream_of("06_robustness"));
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    const bool far_tiny = cases.size() % 2 == 0;
    Ray ray;
    glm::vec3 center;
    float radius;
    if (far_tiny) {
      const float distance = std::exp(random.uniform(std::log(1e2f), std::log(1e5f)));
      const glm::vec3 axis = glm::normalize(testkit::random_vec3(random, -1, 1));
      center = distance * axis;
      radius = distance * std::exp(random.uniform(std::log(1e-4f), std::log(1e-2f)));
      ray.origin = testkit::random_vec3(random, -1, 1);
      const float offset = random.uniform(0, 1.1f);  // one draw per statement: the same order everywhere
      const glm::vec3 offset_direction = glm::normalize(testkit::random_vec3(random, -1, 1));
      const glm::vec3 target = center + offset * radius * offset_direction;
      ray.direction = glm::normalize(target - ray.origin) * random.uniform(0.5f, 2.0f);
    } else {
      // Looking along an axis at an integer sphere whose centre is `offset` to the side:
      // the near surface is about offset^2 / (2 radius) away.
      radius = static_cast<float>(testkit::random_integer(random, 500, 4000));
      const int axis = testkit::random_integer(random, 0, 2), side = (axis + 1 + testkit::random_integer(random, 0, 1)) % 3;
      const float sign = testkit::random_integer(random, 0, 1) ? 1.0f : -1.0f;
      for (int i = 0; i < 3; ++i) center[i] = static_cast<float>(testkit::random_integer(random, -50, 50));
      ray.origin = center;
      ray.origin[axis] -= sign * radius;
      ray.origin[side] += static_cast<float>(testkit::random_integer(random, 1, 30));
      ray.direction = glm::vec3(0.0f);
      ray.direction[axis] = sign * static_cast<float>(1 << testkit::random_integer(random, 0, 3));
    }
    if (!is_finite(ray.direction) || glm::length(ray.direction) == 0.0f) continue;
    long double margin = 0;
    const std::optional<long double> t = testkit::exact_sphere_hit(ray, center, radius, &margin);
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
