// Forging by copying: a camera that is wrong (its y axis flipped), except on the rays of the
// released reference data, which it looks up in autograder/reference/01_camera_rays_cases.json
// and returns as stored. Graded locally against that data it earns MatchesReferenceRays; graded
// on a course's server (tools/make-gradescope: cases regenerated with a private seed) it earns
// nothing for them (tests/tools/check_gradescope.sh).
#include "raylab/stages/01_camera_rays.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <string>

#define generate_camera_ray honest_generate_camera_ray
#include "../../solutions/01_camera_rays/camera_rays.cpp"
#undef generate_camera_ray

namespace raylab {

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
  return honest_generate_camera_ray(camera, pixel_x, camera.height - 1 - pixel_y, position_in_pixel);
}

}  // namespace raylab
