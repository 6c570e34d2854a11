// The reference cases of stage 01_camera_rays: random cameras and pixels, with the reference ray directions.
// autograder-regenerate writes them to autograder/reference/01_camera_rays_cases.json with the answers
// of the solutions it is linked with; the suite (01_camera_rays_test.cpp) grades against them.
#include "support.h"

#include "raylab/camera.h"
#include "raylab/stages/01_camera_rays.h"

#include <cmath>
#include <optional>
#include <stdexcept>

namespace raylab::grading {
namespace {

using nlohmann::json;

json camera_cases(std::uint32_t seed, int count) {
  Pcg32 random(seed, testkit::stream_of("01_camera_rays"));
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    Camera camera;
    camera.position = testkit::random_vec3(random, -10, 10);
    camera.look_at = camera.position + testkit::random_vec3(random, -1, 1);
    camera.up = testkit::random_vec3(random, -1, 1);
    camera.fov_y_degrees = random.uniform(20, 120);
    camera.width = testkit::random_integer(random, 1, 1920);
    camera.height = testkit::random_integer(random, 1, 1080);
    try {
      validate_camera(camera);
    } catch (const std::invalid_argument&) {
      continue;
    }
    // Keep cameras whose basis is well conditioned: up far from the view direction.
    const glm::vec3 forward = glm::normalize(camera.look_at - camera.position);
    if (glm::length(glm::cross(forward, glm::normalize(camera.up))) < 0.2f) continue;
    const int x = testkit::random_integer(random, 0, camera.width - 1), y = testkit::random_integer(random, 0, camera.height - 1);
    cases.push_back({{"id", cases.size()}, {"position", to_json(camera.position)}, {"look_at", to_json(camera.look_at)},
                     {"up", to_json(camera.up)}, {"fov_y_degrees", camera.fov_y_degrees}, {"width", camera.width},
                     {"height", camera.height}, {"pixel_x", x}, {"pixel_y", y},
                     {"direction", to_json(generate_camera_ray(camera, x, y).direction)}});
  }
  return cases;
}

const bool kRegistered =
    register_reference_data("01_camera_rays", {[](std::uint32_t seed) { return json{{"cases", camera_cases(seed, 200)}}; }});

}  // namespace
}  // namespace raylab::grading
