// Grader self-test submission (stage 01_camera_rays): two mistakes at once, the camera code a
// real GAMES101 student wrote first: x = (i - width/2) / width * scale * aspect and
// y = (height/2 - j) / height * scale. Integer pixel indices (no pixel centre, no +0.5) and no
// factor 2 of `2 ndc - 1` (the screen is half as large). Both hints must fire.
#include "raylab/stages/01_camera_rays.h"

#include <cmath>

namespace raylab {

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  (void)position_in_pixel;  // integer pixel indices: the corner, whatever the caller asks
  const float width = static_cast<float>(camera.width);
  const float height = static_cast<float>(camera.height);
  const float scale = std::tan(degrees_to_radians(camera.fov_y_degrees) * 0.5f);
  const float aspect = camera.aspect_ratio();
  const float x = (static_cast<float>(pixel_x) - width / 2.0f) / width * scale * aspect;
  const float y = (height / 2.0f - static_cast<float>(pixel_y)) / height * scale;
  const glm::vec3 forward = glm::normalize(camera.look_at - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 true_up = glm::cross(right, forward);
  Ray ray;
  ray.origin = camera.position;
  ray.direction = glm::normalize(x * right + y * true_up + forward);
  return ray;
}

}  // namespace raylab
