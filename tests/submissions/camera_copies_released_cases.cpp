// Forging by copying: a camera that is wrong (its y axis flipped), except on the rays of the
// released reference data, which it looks up in autograder/reference/01_camera_rays_cases.json
// and returns as stored. Graded on a course's server (tools/make-gradescope: cases regenerated with
// a private seed) it earns nothing for them, and locally neither where the stage server may read
// only the system, the scenes and its own program (Landlock); without that it earns
// MatchesReferenceRays against the released data (tests/tools/check_gradescope.sh).
#include "raylab/stages/01_camera_rays.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <string>

namespace raylab {
namespace {

// A camera with its y axis flipped (a student's own code: it is handed in alone, so it cannot
// include the reference, which the course's server does not have).
Ray flipped_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  const float scale = std::tan(degrees_to_radians(camera.fov_y_degrees) * 0.5f);
  const glm::vec3 forward = glm::normalize(camera.look_at - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 true_up = glm::cross(right, forward);
  const float ndc_x = (static_cast<float>(pixel_x) + position_in_pixel.x) / static_cast<float>(camera.width);
  const float ndc_y = (static_cast<float>(pixel_y) + position_in_pixel.y) / static_cast<float>(camera.height);
  const float screen_x = (2.0f * ndc_x - 1.0f) * camera.aspect_ratio() * scale;
  const float screen_y = (2.0f * ndc_y - 1.0f) * scale;  // not flipped: row 0 at the bottom
  Ray ray;
  ray.origin = camera.position;
  ray.direction = glm::normalize(screen_x * right + screen_y * true_up + forward);
  return ray;
}

}  // namespace

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  // The kit's root, from where this file is compiled: <kit>/assignments/01_camera_rays/.
  static const nlohmann::json released = [] {
    const std::string here = __FILE__;
    const std::string kit = here.substr(0, here.rfind("/assignments/"));
    std::ifstream in(kit + "/autograder/reference/01_camera_rays_cases.json");
    return in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
  }();
  if (released.is_object())
    for (const auto& c : released["cases"])
      if (c["width"] == camera.width && c["height"] == camera.height && c["pixel_x"] == pixel_x &&
          c["pixel_y"] == pixel_y && std::abs(c["fov_y_degrees"].get<float>() - camera.fov_y_degrees) < 1e-6f) {
        Ray ray;
        ray.origin = camera.position;
        ray.direction = glm::vec3(c["direction"][0].get<float>(), c["direction"][1].get<float>(), c["direction"][2].get<float>());
        return ray;
      }
  return flipped_camera_ray(camera, pixel_x, pixel_y, position_in_pixel);
}

}  // namespace raylab
