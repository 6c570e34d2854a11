// The reference cases of stage 04_box: random rays at random boxes (flat boxes and zero direction components among them).
// autograder-regenerate writes them to autograder/reference/04_box_cases.json with the answers
// of the solutions it is linked with; the suite (04_box_test.cpp) grades against them.
#include "support.h"

#include "raylab/stages/04_box.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace raylab::grading {
namespace {

using nlohmann::json;

json box_cases(std::uint32_t seed, int count) {
  Pcg32 random(seed, testkit::stream_of("04_box"));
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    const glm::vec3 corner = testkit::random_vec3(random, -10, 10);
    glm::vec3 size = testkit::random_vec3(random, 0, 5);
    if (random.uniform(0, 1) < 0.15f) size[testkit::random_integer(random, 0, 2)] = 0.0f;  // flat boxes
    const Bounds3 box{corner, corner + size};
    const bool inside = random.uniform(0, 1) < 0.15f;
    Ray ray;
    ray.origin = inside ? box.min + testkit::random_vec3(random, 0, 1) * size
                        : testkit::random_vec3(random, -20, 20);
    const glm::vec3 target_in_box = testkit::random_vec3(random, -0.5f, 1.5f);  // one draw per statement:
    const glm::vec3 jitter = testkit::random_vec3(random, -1, 1);              // the same order everywhere
    const glm::vec3 target = box.min + target_in_box * size + jitter;
    if (glm::length(target - ray.origin) < 1e-3f) continue;
    ray.direction = glm::normalize(target - ray.origin) * random.uniform(0.2f, 5.0f);
    if (random.uniform(0, 1) < 0.2f) ray.direction[testkit::random_integer(random, 0, 2)] = testkit::random_integer(random, 0, 1) ? 0.0f : -0.0f;
    if (glm::length(ray.direction) == 0.0f) continue;
    ray.t_min = random.uniform(0, 1) < 0.3f ? random.uniform(0, 3) : 0.0f;
    const bool finite_t_max = random.uniform(0, 1) < 0.3f;
    ray.t_max = finite_t_max ? random.uniform(1, 30) : kInfinity;
    // Leave out cases a correct float implementation may decide either way (in double): a
    // slab interval that almost closes, or an entry or exit within a hair of t_min or t_max.
    double enter = ray.t_min, exit = ray.t_max;
    bool degenerate = false;
    for (int axis = 0; axis < 3; ++axis) {
      const double o = ray.origin[axis], d = ray.direction[axis], lo = box.min[axis], hi = box.max[axis];
      if (d == 0.0) {
        if (std::fabs(o - lo) < 1e-4 || std::fabs(o - hi) < 1e-4) degenerate = true;
        if (o < lo || o > hi) exit = -1.0;  // misses the slab
        continue;
      }
      double t0 = (lo - o) / d, t1 = (hi - o) / d;
      if (t0 > t1) std::swap(t0, t1);
      enter = std::max(enter, t0);
      exit = std::min(exit, t1);
    }
    const double gap = exit - enter;
    if (degenerate || (std::isfinite(gap) && std::fabs(gap) < 1e-3 * std::max(1.0, std::fabs(enter)))) continue;
    if (std::fabs(enter - ray.t_min) < 1e-4 && enter != ray.t_min) continue;
    const std::optional<float> t = intersect_ray_box(ray, ray_direction_inverse_of(ray), box);
    cases.push_back({{"id", cases.size()}, {"origin", to_json(ray.origin)}, {"direction", to_json(ray.direction)},
                     {"t_min", ray.t_min}, {"t_max", finite_t_max ? json(ray.t_max) : json(nullptr)},
                     {"min", to_json(box.min)}, {"max", to_json(box.max)}, {"t_enter", t ? json(*t) : json(nullptr)}});
  }
  return cases;
}

const bool kRegistered =
    register_reference_data("04_box", {[](std::uint32_t seed) { return json{{"cases", box_cases(seed, 400)}}; }});

}  // namespace
}  // namespace raylab::grading
