// The reference cases of stage 02_sphere: random rays at random spheres, about half of them hits.
// autograder-regenerate writes them to autograder/reference/02_sphere_cases.json with the answers
// of the solutions it is linked with; the suite (02_sphere_test.cpp) grades against them.
#include "support.h"

#include "raylab/stages/02_sphere.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace raylab::grading {
namespace {

using nlohmann::json;

json sphere_cases(std::uint32_t seed, int count) {
  Pcg32 random(seed, testkit::stream_of("02_sphere"));
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    const glm::vec3 center = testkit::random_vec3(random, -10, 10);
    const float radius = random.uniform(0.1f, 5.0f);
    const bool inside = random.uniform(0, 1) < 0.15f;
    const glm::vec3 origin = inside ? center + testkit::random_vec3(random, -0.5f, 0.5f) * radius : testkit::random_vec3(random, -20, 20);
    // Aim near the sphere so that about half the rays hit.
    const glm::vec3 target = center + testkit::random_vec3(random, -1.6f, 1.6f) * radius;
    if (glm::length(target - origin) < 1e-3f) continue;
    const glm::vec3 direction = glm::normalize(target - origin) * random.uniform(0.2f, 5.0f);
    Ray ray;
    ray.origin = origin;
    ray.direction = direction;
    ray.t_min = random.uniform(0, 1) < 0.3f ? random.uniform(0, 2) : 0.0f;
    const bool finite_t_max = random.uniform(0, 1) < 0.3f;
    ray.t_max = finite_t_max ? random.uniform(1, 30) : kInfinity;
    // Leave out cases a correct float implementation may decide either way: near-tangent
    // rays and hits within a hair of t_min or t_max (computed in double).
    const glm::dvec3 o(origin - center), d(direction);
    const double a = glm::dot(d, d), half_b = glm::dot(o, d), c = glm::dot(o, o) - double(radius) * radius;
    const double discriminant = half_b * half_b - a * c;
    if (std::fabs(discriminant) < 1e-3 * a * double(radius) * radius) continue;
    bool ambiguous = false;
    if (discriminant > 0)
      for (double root : {(-half_b - std::sqrt(discriminant)) / a, (-half_b + std::sqrt(discriminant)) / a})
        for (double limit : {double(ray.t_min), double(ray.t_max)})
          if (std::isfinite(limit) && std::fabs(root - limit) < 1e-3 * std::max(1.0, std::fabs(limit))) ambiguous = true;
    if (ambiguous) continue;
    const std::optional<float> t = intersect_ray_sphere(ray, center, radius);
    cases.push_back({{"id", cases.size()}, {"origin", to_json(origin)}, {"direction", to_json(direction)},
                     {"t_min", ray.t_min}, {"t_max", finite_t_max ? json(ray.t_max) : json(nullptr)},
                     {"center", to_json(center)}, {"radius", radius}, {"t_hit", t ? json(*t) : json(nullptr)}});
  }
  return cases;
}

const bool kRegistered =
    register_reference_data("02_sphere", {[](std::uint32_t seed) { return json{{"cases", sphere_cases(seed, 400)}}; }});

}  // namespace
}  // namespace raylab::grading
