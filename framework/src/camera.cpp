#include "raylab/camera.h"

#include <cmath>
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

namespace {

// The camera's frame as the exact camera rays build it, and how far in front of it a point must
// be to be drawn: a thousandth of the distance to look_at.
struct CameraFrame {
  glm::dvec3 position, forward, right, up;
  double near_distance;
  explicit CameraFrame(const Camera& camera) : position(camera.position) {
    const glm::dvec3 view = glm::dvec3(camera.look_at) - position;
    forward = glm::normalize(view);
    right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
    up = glm::cross(right, forward);
    near_distance = 1e-3 * glm::length(view);
  }
  double depth(const glm::dvec3& point) const { return glm::dot(point - position, forward); }
  glm::vec2 raster(const Camera& camera, const glm::dvec3& point) const {
    const glm::dvec3 d = point - position;
    const double z = glm::dot(d, forward);
    const double scale = std::tan(static_cast<double>(camera.fov_y_degrees) * (3.14159265358979323846 / 180.0) * 0.5);
    const double aspect = static_cast<double>(camera.width) / camera.height;
    const double ndc_x = (glm::dot(d, right) / (z * aspect * scale) + 1.0) * 0.5;
    const double ndc_y = (1.0 - glm::dot(d, up) / (z * scale)) * 0.5;
    return {static_cast<float>(ndc_x * camera.width), static_cast<float>(ndc_y * camera.height)};
  }
};

}  // namespace

std::optional<glm::vec2> project_to_raster(const Camera& camera, const glm::vec3& point) {
  const CameraFrame frame(camera);
  if (!(frame.depth(point) >= frame.near_distance)) return std::nullopt;
  return frame.raster(camera, point);
}

std::optional<std::array<glm::vec2, 2>> project_segment_to_raster(const Camera& camera, const glm::vec3& a,
                                                                   const glm::vec3& b) {
  const CameraFrame frame(camera);
  glm::dvec3 from(a), to(b);
  const double depth_from = frame.depth(from), depth_to = frame.depth(to);
  if (!(depth_from >= frame.near_distance) && !(depth_to >= frame.near_distance)) return std::nullopt;
  // Cut at the near distance the end that is behind it.
  if (depth_from < frame.near_distance)
    from = to + (from - to) * ((depth_to - frame.near_distance) / (depth_to - depth_from));
  else if (depth_to < frame.near_distance)
    to = from + (to - from) * ((depth_from - frame.near_distance) / (depth_from - depth_to));
  return std::array<glm::vec2, 2>{frame.raster(camera, from), frame.raster(camera, to)};
}

std::ostream& operator<<(std::ostream& out, const Camera& camera) {
  return out << "camera at " << camera.position << " looking at " << camera.look_at << " up "
             << camera.up << ", fov_y " << camera.fov_y_degrees << " degrees, " << camera.width
             << "x" << camera.height;
}

}  // namespace raylab
