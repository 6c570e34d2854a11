// The reference cases of stage 03_triangle: random rays at random triangles, about half of them hits.
// autograder-regenerate writes them to autograder/reference/03_triangle_cases.json with the answers
// of the solutions it is linked with; the suite (03_triangle_test.cpp) grades against them.
#include "support.h"

#include "raylab/stages/03_triangle.h"

#include <cmath>
#include <optional>

namespace raylab::grading {
namespace {

using nlohmann::json;

json triangle_cases(std::uint32_t seed, int count) {
  Pcg32 random(seed, testkit::stream_of("03_triangle"));
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    const glm::vec3 p0 = testkit::random_vec3(random, -5, 5), p1 = testkit::random_vec3(random, -5, 5), p2 = testkit::random_vec3(random, -5, 5);
    const glm::vec3 normal = glm::cross(p1 - p0, p2 - p0);
    if (glm::length(normal) < 0.5f) continue;  // keep triangles with a clear area
    // Aim at a point with barycentrics in [-0.3, 1.3]: about half inside.
    const float b1 = random.uniform(-0.3f, 1.3f), b2 = random.uniform(-0.3f, 1.3f);
    const float b0 = 1.0f - b1 - b2;
    const float margin = 1e-3f;
    if (std::fabs(b1) < margin || std::fabs(b2) < margin || std::fabs(b0) < margin) continue;  // on an edge: either answer
    const glm::vec3 target = b0 * p0 + b1 * p1 + b2 * p2;
    const glm::vec3 origin = target + testkit::random_vec3(random, -8, 8);
    const glm::vec3 direction = (target - origin) * random.uniform(0.2f, 3.0f);
    if (std::fabs(glm::dot(glm::normalize(direction), glm::normalize(normal))) < 0.05f) continue;  // near-parallel
    Ray ray;
    ray.origin = origin;
    ray.direction = direction;
    ray.t_min = 0.0f;
    const bool finite_t_max = random.uniform(0, 1) < 0.3f;
    // t of the target is 1 / scale; keep t_max away from it.
    const float t_target = glm::length(target - origin) / glm::length(direction);
    ray.t_max = finite_t_max ? t_target * (random.uniform(0, 1) < 0.5f ? 0.7f : 1.3f) : kInfinity;
    const std::optional<TriangleHit> hit = intersect_ray_triangle(ray, p0, p1, p2);
    cases.push_back({{"id", cases.size()}, {"origin", to_json(origin)}, {"direction", to_json(direction)},
                     {"t_min", ray.t_min}, {"t_max", finite_t_max ? json(ray.t_max) : json(nullptr)},
                     {"p0", to_json(p0)}, {"p1", to_json(p1)}, {"p2", to_json(p2)},
                     {"hit", hit ? json::array({hit->t_hit, hit->barycentric_b1, hit->barycentric_b2}) : json(nullptr)}});
  }
  return cases;
}

const bool kRegistered =
    register_reference_data("03_triangle", {[](std::uint32_t seed) { return json{{"cases", triangle_cases(seed, 400)}}; }});

}  // namespace
}  // namespace raylab::grading
