// Hostile: the reference camera, which on its first call in each process writes "passed" report
// lines to every descriptor it may have inherited, the grader's own pipes included. What it
// writes into the reply pipe is not an answer: every call it corrupts is lost, so stage
// 01_camera_rays scores 0 and the later stages lose only their image tests (the picture is
// rendered with this camera).
#include "hostile.h"

#define generate_camera_ray honest_generate_camera_ray
#include "../../solutions/01_camera_rays/camera_rays.cpp"
#undef generate_camera_ray

namespace raylab {

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel = glm::vec2(0.5f));

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  static bool attacked = false;
  if (!attacked) {
    attacked = true;
    hostile::write_to_inherited_descriptors(true);
  }
  return honest_generate_camera_ray(camera, pixel_x, pixel_y, position_in_pixel);
}

}  // namespace raylab
