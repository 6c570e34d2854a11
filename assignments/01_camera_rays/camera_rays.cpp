// Stage 01_camera_rays: from a pixel to a world-space ray.     Handout: docs/01_camera_rays.md
//
// WHAT YOU RECEIVE
//   camera.position       where the eye is (world space)
//   camera.look_at        a point the eye looks at; the view direction is look_at - position
//   camera.up             roughly "up" in the world; not unit length, not exactly perpendicular
//                         to the view direction
//   camera.fov_y_degrees  the FULL vertical field of view, in DEGREES (raylab/math.h has
//                         degrees_to_radians)
//   camera.width, camera.height   the image size in pixels; camera.aspect_ratio() = width / height
//   pixel_x, pixel_y      the pixel: column 0..width-1 from the left, row 0..height-1 from the TOP
//   position_in_pixel     where in that pixel the ray must pass, each coordinate in [0, 1) from
//                         the pixel's top-left corner; (0.5, 0.5) is its CENTRE (the renderer
//                         passes the centre at 1 sample per pixel, other points to anti-alias)
//
// WHAT YOU RETURN
//   A Ray with origin = camera.position and a UNIT-LENGTH direction through raster point
//   (pixel_x + position_in_pixel.x, pixel_y + position_in_pixel.y) on the image plane; for the
//   centre, (pixel_x + 0.5, pixel_y + 0.5). Leave t_min = 0 and t_max = infinity (the Ray
//   defaults).
//
// CONVENTIONS (docs/conventions.md, "Raster and camera")
//   Camera space: the eye at the origin looking down -z, +y up, +x right. The image plane is
//   at distance 1 in front of the eye; the field of view spans its height, and the aspect
//   ratio its width. Row 0 is the TOP of the picture.
//
// READ docs/01_camera_rays.md, section 2 (raster -> NDC -> screen -> world, with a worked
//   example); section 4 lists the common mistakes, which the autograder's hints name.
//
// HOW TO CHECK
//   build/bin/autograder --stage 01_camera_rays, then build/bin/raylab render scenes/whitted.json -o out.png
#include "raylab/error.h"
#include "raylab/stages/01_camera_rays.h"

namespace raylab {

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  (void)camera;
  (void)pixel_x;
  (void)pixel_y;
  (void)position_in_pixel;
  // Delete the line below when you write the function.
  throw NotImplemented("generate_camera_ray");
}

}  // namespace raylab
