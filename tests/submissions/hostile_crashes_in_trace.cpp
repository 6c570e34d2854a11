// Hostile: camera_y_not_flipped's camera, which crashes once the grader's picture (320x240) has
// asked for every pixel and a pixel comes again: the call that traces the failing picture's worst
// pixel for the report. A trace only shows, so its crash must cost nothing: this submission
// scores exactly what camera_y_not_flipped scores, its picture failing with its hint, without a
// trace note.
#define generate_camera_ray honest_generate_camera_ray
#include "camera_y_not_flipped.cpp"
#undef generate_camera_ray

#include <vector>

namespace raylab {

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel = glm::vec2(0.5f));

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  constexpr int kWidth = 320, kHeight = 240;  // the grader's pictures (stage_image.h)
  static std::vector<bool> asked(kWidth * kHeight, false);
  static int pixels_asked = 0;
  if (camera.width == kWidth && camera.height == kHeight && pixel_x >= 0 && pixel_y >= 0 && pixel_x < kWidth &&
      pixel_y < kHeight) {
    const std::size_t pixel = static_cast<std::size_t>(pixel_y) * kWidth + static_cast<std::size_t>(pixel_x);
    if (asked[pixel] && pixels_asked == kWidth * kHeight) {
      volatile int* nowhere = nullptr;
      *nowhere = 1;  // the deliberate crash
    }
    if (!asked[pixel]) ++pixels_asked;
    asked[pixel] = true;
  }
  return honest_generate_camera_ray(camera, pixel_x, pixel_y, position_in_pixel);
}

}  // namespace raylab
