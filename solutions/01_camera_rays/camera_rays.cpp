// Reference solution, stage 01_camera_rays. The contract is in
// assignments/01_camera_rays/camera_rays.cpp and docs/01_camera_rays.md.
#include "raylab/stages/01_camera_rays.h"

#include <cmath>

namespace raylab {

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  // Raster -> NDC in [0, 1] at the given point of the pixel (its centre: + 0.5).
  const float ndc_x = (static_cast<float>(pixel_x) + position_in_pixel.x) / static_cast<float>(camera.width);
  const float ndc_y = (static_cast<float>(pixel_y) + position_in_pixel.y) / static_cast<float>(camera.height);
  // NDC -> screen space on the plane z = -1: x in [-aspect*scale, aspect*scale], y flipped so
  // that row 0 is the top of the picture.
  const float scale = std::tan(degrees_to_radians(camera.fov_y_degrees) * 0.5f);
  const float screen_x = (2.0f * ndc_x - 1.0f) * camera.aspect_ratio() * scale;
  const float screen_y = (1.0f - 2.0f * ndc_y) * scale;
  // Camera space -> world space: an orthonormal basis from the view direction and `up`.
  const glm::vec3 forward = glm::normalize(camera.look_at - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 true_up = glm::cross(right, forward);

  Ray ray;
  ray.origin = camera.position;
  ray.direction = glm::normalize(screen_x * right + screen_y * true_up + forward);
  return ray;
}

}  // namespace raylab
