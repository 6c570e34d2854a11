#include "raylab/camera.h"

#include <sstream>
#include <stdexcept>
#include <string>

namespace raylab {

void validate_camera(const Camera& camera) {
  auto fail = [](const std::string& what) { throw std::invalid_argument(what); };
  if (!is_finite(camera.position) || !is_finite(camera.look_at) || !is_finite(camera.up))
    fail("position, look_at and up must be finite numbers");
  const glm::vec3 view = camera.look_at - camera.position;
  if (glm::dot(view, view) == 0.0f) fail("look_at must differ from position");
  if (glm::dot(camera.up, camera.up) == 0.0f) fail("up must not be the zero vector");
  const glm::vec3 side = glm::cross(glm::normalize(view), glm::normalize(camera.up));
  if (glm::dot(side, side) < 1e-12f) fail("up must not be parallel to the view direction");
  if (!(camera.fov_y_degrees > 0.0f && camera.fov_y_degrees < 180.0f))
    fail("fov_y_degrees must be in (0, 180), got " + std::to_string(camera.fov_y_degrees));
  const std::string size = std::to_string(camera.width) + "x" + std::to_string(camera.height);
  if (camera.width <= 0 || camera.height <= 0) fail("width and height must be positive, got " + size);
  if (camera.width > kMaxImageSide || camera.height > kMaxImageSide ||
      static_cast<long long>(camera.width) * camera.height > kMaxImagePixels)
    fail("an image of " + size + " is over the limit (" + std::to_string(kMaxImageSide) + " a side, " +
         std::to_string(kMaxImagePixels) + " pixels in all)");
}

std::ostream& operator<<(std::ostream& out, const Camera& camera) {
  return out << "camera at " << camera.position << " looking at " << camera.look_at << " up "
             << camera.up << ", fov_y " << camera.fov_y_degrees << " degrees, " << camera.width
             << "x" << camera.height;
}

}  // namespace raylab
