// Grader self-test submission (stage 01_camera_rays): CORRECT, but computed in double
// precision throughout and rounded to float at the end.
#include "raylab/stages/01_camera_rays.h"

#include <glm/glm.hpp>

#include <cmath>

namespace raylab {

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  const double ndc_x = (pixel_x + static_cast<double>(position_in_pixel.x)) / camera.width;
  const double ndc_y = (pixel_y + static_cast<double>(position_in_pixel.y)) / camera.height;
  const double scale = std::tan(camera.fov_y_degrees * 3.14159265358979323846 / 360.0);
  const double aspect = static_cast<double>(camera.width) / camera.height;
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.look_at) - glm::dvec3(camera.position));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
  const glm::dvec3 true_up = glm::cross(right, forward);
  const glm::dvec3 direction = (2.0 * ndc_x - 1.0) * aspect * scale * right + (1.0 - 2.0 * ndc_y) * scale * true_up + forward;
  Ray ray;
  ray.origin = camera.position;
  ray.direction = glm::vec3(glm::normalize(direction));
  return ray;
}

}  // namespace raylab
