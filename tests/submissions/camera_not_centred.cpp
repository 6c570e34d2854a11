// Grader self-test submission (stage 01_camera_rays): mistake: 2 ndc without the -1 (the screen starts at the view's centre)
#include "raylab/stages/01_camera_rays.h"

#include <cmath>

namespace raylab {

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  const float aspect = camera.aspect_ratio();
  const float ndc_x = (static_cast<float>(pixel_x) + position_in_pixel.x) / static_cast<float>(camera.width);
  const float ndc_y = (static_cast<float>(pixel_y) + position_in_pixel.y) / static_cast<float>(camera.height);
  const float scale = std::tan(degrees_to_radians(camera.fov_y_degrees) * 0.5f);
  const float screen_x = 2.0f * ndc_x * aspect * scale;
  const float screen_y = (1.0f - 2.0f * ndc_y) * scale;
  const glm::vec3 forward = glm::normalize(camera.look_at - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 true_up = glm::cross(right, forward);
  Ray ray;
  ray.origin = camera.position;
  ray.direction = glm::normalize(screen_x * right + screen_y * true_up + forward);
  return ray;
}

}  // namespace raylab
