// Grader self-test submissions of stage 01_camera_rays that break one rule of the contract each
// share this camera: a submission file sets the flags of its mistake and includes this file.
//   #define CAMERA_VARIANT(v) v.normalise_direction = false
//   #include "camera_variant.h"
// (The older camera submissions are whole files of their own.)
#pragma once

#include "raylab/math.h"
#include "raylab/stages/01_camera_rays.h"

#include <cmath>

namespace raylab::submission {

struct CameraVariant {
  bool origin_at_position = true;   // false: every ray starts at the world's origin
  bool normalise_direction = true;  // false: the direction through the image plane as it is
  float t_min = 0.0f;               // > 0: an epsilon of the student's own instead of 0
  bool use_look_at = true;          // false: the camera looks down -z, whatever look_at says
};

inline Ray camera_ray_variant(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel,
                              const CameraVariant& v) {
  const float scale = std::tan(degrees_to_radians(camera.fov_y_degrees) * 0.5f);
  const float ndc_x = (static_cast<float>(pixel_x) + position_in_pixel.x) / static_cast<float>(camera.width);
  const float ndc_y = (static_cast<float>(pixel_y) + position_in_pixel.y) / static_cast<float>(camera.height);
  const float screen_x = (2.0f * ndc_x - 1.0f) * camera.aspect_ratio() * scale;
  const float screen_y = (1.0f - 2.0f * ndc_y) * scale;
  const glm::vec3 forward = v.use_look_at ? glm::normalize(camera.look_at - camera.position) : glm::vec3(0, 0, -1);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 true_up = glm::cross(right, forward);
  const glm::vec3 direction = screen_x * right + screen_y * true_up + forward;
  Ray ray;
  ray.origin = v.origin_at_position ? camera.position : glm::vec3(0.0f);
  ray.direction = v.normalise_direction ? glm::normalize(direction) : direction;
  ray.t_min = v.t_min;
  return ray;
}

}  // namespace raylab::submission

namespace raylab {
Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  static const submission::CameraVariant variant = [] {
    submission::CameraVariant v;
    CAMERA_VARIANT(v);
    return v;
  }();
  return submission::camera_ray_variant(camera, pixel_x, pixel_y, position_in_pixel, variant);
}
}  // namespace raylab
