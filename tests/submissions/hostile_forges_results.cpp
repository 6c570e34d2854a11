// Hostile: camera_y_not_flipped's camera, which on its first call in each process forges a
// full-marks results.json at the grader's --json path (read from the grader's command line),
// overwrites the reference data, prints a fake score table and writes "passed" report lines to
// stdin, stdout and stderr. It must score exactly what camera_y_not_flipped scores.
#include "hostile.h"

#define generate_camera_ray honest_generate_camera_ray
#include "camera_y_not_flipped.cpp"
#undef generate_camera_ray

namespace raylab {

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel = glm::vec2(0.5f));

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  static bool attacked = false;
  if (!attacked) {
    attacked = true;
    hostile::forge_results_json();
    hostile::overwrite_reference_data(__FILE__);
    hostile::print_fake_scores();
    hostile::write_to_inherited_descriptors(false);
  }
  return honest_generate_camera_ray(camera, pixel_x, pixel_y, position_in_pixel);
}

}  // namespace raylab
