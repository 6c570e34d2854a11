// Grader self-test submission (stage 01_camera_rays): CORRECT, but a different camera basis
// computation: the inverse of glm::lookAt's view matrix, applied to a camera-space direction.
#include "raylab/stages/01_camera_rays.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace raylab {

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  const glm::mat4 camera_from_world = glm::lookAt(camera.position, camera.look_at, camera.up);
  const glm::mat4 world_from_camera = glm::inverse(camera_from_world);
  const float tan_half = std::tan(glm::radians(camera.fov_y_degrees) / 2.0f);
  const float x = (2.0f * (static_cast<float>(pixel_x) + position_in_pixel.x) / static_cast<float>(camera.width) - 1.0f) *
                  tan_half * static_cast<float>(camera.width) / static_cast<float>(camera.height);
  const float y = (1.0f - 2.0f * (static_cast<float>(pixel_y) + position_in_pixel.y) / static_cast<float>(camera.height)) * tan_half;
  Ray ray;
  ray.origin = camera.position;
  ray.direction = glm::normalize(glm::vec3(world_from_camera * glm::vec4(x, y, -1.0f, 0.0f)));
  return ray;
}

}  // namespace raylab
