// Reference solution, stage 01_camera_rays. The contract is in
// assignments/01_camera_rays/camera_rays.cpp and docs/01_camera_rays.md.
#include "raylab/stages/01_camera_rays.h"

#include <cmath>
#include <cstring>

namespace raylab {
namespace {

// What every ray of one camera shares: the screen's scale and the camera's basis.
struct CameraFrame {
  float scale = 0.0f;         // tan(fov_y / 2): half the image plane's height at distance 1
  float aspect_ratio = 0.0f;  // camera.aspect_ratio()
  glm::vec3 forward{0.0f}, right{0.0f}, true_up{0.0f};
};

CameraFrame frame_of(const Camera& camera) {
  CameraFrame frame;
  frame.scale = std::tan(degrees_to_radians(camera.fov_y_degrees) * 0.5f);
  frame.aspect_ratio = camera.aspect_ratio();
  // Camera space -> world space: an orthonormal basis from the view direction and `up`.
  frame.forward = glm::normalize(camera.look_at - camera.position);
  frame.right = glm::normalize(glm::cross(frame.forward, camera.up));
  frame.true_up = glm::cross(frame.right, frame.forward);
  return frame;
}

// The same bits in every field (so -0 and 0, or two NaNs, are told apart as the arithmetic
// would tell them apart).
template <typename T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// A render asks for a ray per pixel sample, all of the same camera: each thread keeps the frame
// of the last camera it saw instead of calling tan, normalize and cross again for every ray (the
// GAMES101 peer computes them once too). The same operations as without the cache, so the same
// bits.
const CameraFrame& frame_of_last_camera(const Camera& camera) {
  thread_local bool known = false;
  thread_local Camera last;
  thread_local CameraFrame frame;
  if (!known || !same_bits(camera.position, last.position) || !same_bits(camera.look_at, last.look_at) ||
      !same_bits(camera.up, last.up) || !same_bits(camera.fov_y_degrees, last.fov_y_degrees) ||
      camera.width != last.width || camera.height != last.height) {
    frame = frame_of(camera);
    last = camera;
    known = true;
  }
  return frame;
}

}  // namespace

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  const CameraFrame& frame = frame_of_last_camera(camera);
  // Raster -> NDC in [0, 1] at the given point of the pixel (its centre: + 0.5).
  const float ndc_x = (static_cast<float>(pixel_x) + position_in_pixel.x) / static_cast<float>(camera.width);
  const float ndc_y = (static_cast<float>(pixel_y) + position_in_pixel.y) / static_cast<float>(camera.height);
  // NDC -> screen space on the plane z = -1: x in [-aspect*scale, aspect*scale], y flipped so
  // that row 0 is the top of the picture.
  const float screen_x = (2.0f * ndc_x - 1.0f) * frame.aspect_ratio * frame.scale;
  const float screen_y = (1.0f - 2.0f * ndc_y) * frame.scale;

  Ray ray;
  ray.origin = camera.position;
  ray.direction = glm::normalize(screen_x * frame.right + screen_y * frame.true_up + frame.forward);
  return ray;
}

}  // namespace raylab
