// The pinhole camera of a scene, and the raster conventions every stage shares.
//
// Conventions (docs/01_camera_rays.md):
//   raster space   pixel (i, j): i = column 0..width-1 left to right, j = row 0..height-1 top to
//                  bottom; the pixel's centre is at (i + 0.5, j + 0.5).
//   camera space   the camera at the origin, looking down -z, +y up, +x right.
//   aspect         width / height, applied to x.
//   field of view  fov_y_degrees is the full vertical angle, in degrees.
#pragma once

#include "raylab/math.h"

#include <array>
#include <optional>
#include <ostream>

namespace raylab {

// The largest image raylab renders: a side of 16384 pixels, 64 Mi pixels in all (768 MiB of
// float RGB). Larger sizes are refused with a clear error rather than exhausting memory.
constexpr int kMaxImageSide = 16384;
constexpr long long kMaxImagePixels = 64LL * 1024 * 1024;

struct Camera {
  glm::vec3 position{0.0f};
  glm::vec3 look_at{0.0f, 0.0f, -1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};  // need not be unit length or perpendicular to the view
  float fov_y_degrees = 90.0f;
  int width = 640;
  int height = 480;

  float aspect_ratio() const { return static_cast<float>(width) / static_cast<float>(height); }
};

// Throws std::invalid_argument naming the problem if the camera cannot form an image:
// look_at equal to position, up parallel to the view direction, non-finite values,
// fov outside (0, 180), a size that is not positive or over the limits above.
void validate_camera(const Camera& camera);

std::ostream& operator<<(std::ostream& out, const Camera& camera);

// Where a point of the scene shows on the picture (`raylab view` draws paths and boxes with it):
// its raster position, x to the right and y down from the image's top left corner, so that pixel
// (i, j) covers [i, i + 1) x [j, j + 1); the inverse of the kit's exact camera rays
// (raylab/testkit/exact_tracing.h). nullopt for a point not in front of the camera. The camera
// must be valid (validate_camera).
std::optional<glm::vec2> project_to_raster(const Camera& camera, const glm::vec3& point);

// The part of the segment from a to b that lies in front of the camera, projected; nullopt when
// no part does.
std::optional<std::array<glm::vec2, 2>> project_segment_to_raster(const Camera& camera, const glm::vec3& a,
                                                                   const glm::vec3& b);

}  // namespace raylab
