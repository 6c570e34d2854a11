// Stage 01_camera_rays: from a pixel to a world-space ray.
// Write it in assignments/01_camera_rays/camera_rays.cpp (its comment is the full contract);
// handout: docs/01_camera_rays.md.
#pragma once

#include "raylab/camera.h"
#include "raylab/ray.h"

namespace raylab {

// The primary ray through the centre of pixel (pixel_x, pixel_y): origin at the camera,
// unit-length direction, t_min = 0, t_max = infinity.
Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y);

}  // namespace raylab
