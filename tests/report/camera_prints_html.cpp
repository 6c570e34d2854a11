// Report self-test submission (stage 01_camera_rays): the reference camera, which also prints, once,
// HTML with a script, an image from the network and a forged score, and bytes that are not UTF-8.
// The HTML report must show all of it as text: no element and no script of its own in the page
// (tests/report/CMakeLists.txt).
#define generate_camera_ray reference_generate_camera_ray
#include "../../solutions/01_camera_rays/camera_rays.cpp"
#undef generate_camera_ray

#include <cstdio>

namespace raylab {

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel);

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  static bool printed = false;
  if (!printed) {
    printed = true;
    std::fputs("</pre><img id=\"injected\" src=\"https://example.com/x.png\" onerror=\"document.title = 'forged'\">"
               "<script>document.title = 'forged';</script>\xff\xfe<h1 id=\"forged\">total 164/164</h1>\n",
               stdout);
    std::fflush(stdout);
  }
  return reference_generate_camera_ray(camera, pixel_x, pixel_y, position_in_pixel);
}

}  // namespace raylab
