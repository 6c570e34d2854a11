// Stage 01_camera_rays: from a pixel to a world-space ray.     Handout: docs/01_camera_rays.md
//
// WHAT YOU RECEIVE
//   camera.position       where the eye is (world space)
//   camera.look_at        a point the eye looks at; the view direction is look_at - position
//   camera.up             roughly "up" in the world; not unit length, not exactly perpendicular
//   camera.fov_y_degrees  the full vertical field of view, in DEGREES (std::tan wants radians:
//                         use degrees_to_radians from raylab/math.h)
//   camera.width, camera.height   the image size in pixels; camera.aspect_ratio() = width / height
//   pixel_x, pixel_y      the pixel: column 0..width-1 from the left, row 0..height-1 from the TOP
//   position_in_pixel     where in that pixel the ray must pass, each coordinate in [0, 1) from
//                         the pixel's top-left corner; (0.5, 0.5) is its CENTRE (the renderer
//                         passes the centre at 1 sample per pixel, other points to anti-alias)
//
// WHAT YOU RETURN
//   A Ray with origin = camera.position and a UNIT-LENGTH direction through raster point
//   (pixel_x + position_in_pixel.x, pixel_y + position_in_pixel.y); for the centre, (pixel_x +
//   0.5, pixel_y + 0.5). Leave t_min = 0 and t_max = infinity (the Ray defaults).
//
// THE STEPS (docs/01_camera_rays.md, section 2)
//   1. Raster to NDC in [0, 1]:     ndc_x = (pixel_x + position_in_pixel.x) / width, ndc_y likewise.
//   2. NDC to screen space, on the image plane at distance 1 in front of the eye:
//        scale    = tan(fov_y / 2)                       (half the angle, in radians)
//        screen_x = (2 ndc_x - 1) * aspect * scale       (aspect applies to x only)
//        screen_y = (1 - 2 ndc_y) * scale                (flipped: row 0 is the TOP, +y is up)
//   3. Camera space to world space with an orthonormal basis:
//        forward = normalize(look_at - position), right = normalize(cross(forward, up)),
//        true_up = cross(right, forward)
//        direction = normalize(screen_x * right + screen_y * true_up + forward)
//
// COMMON MISTAKES (the autograder's hints name them)
//   picture upside down (no y flip); aspect applied to y or inverted (height / width);
//   fov not halved or still in degrees; pixel centre missing (+0.5); direction not normalised.
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
  // Start with step 1 above. Delete the line below when you are done.
  throw NotImplemented("generate_camera_ray");
}

}  // namespace raylab
