// Stage 01_camera_rays: from a pixel to a world-space ray.
// Write it in assignments/01_camera_rays/camera_rays.cpp (its comment is the full contract);
// handout: docs/01_camera_rays.md.
#pragma once

#include "raylab/camera.h"
#include "raylab/ray.h"

namespace raylab {

// The primary ray through the point `position_in_pixel` of pixel (pixel_x, pixel_y), i.e.
// through raster point (pixel_x + position_in_pixel.x, pixel_y + position_in_pixel.y):
// origin at the camera, unit-length direction, t_min = 0, t_max = infinity. Each coordinate
// of position_in_pixel is in [0, 1); (0.5, 0.5), the default, is the pixel's centre. The
// renderer passes the centre at 1 sample per pixel and stratified points at more
// (anti-aliasing); the autograder tests the centre first.
Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y,
                        glm::vec2 position_in_pixel = glm::vec2(0.5f));

}  // namespace raylab
