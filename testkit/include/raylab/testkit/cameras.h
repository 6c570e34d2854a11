// The camera the worked examples of stage 01 start from, for the autograder's suite and the
// framework's tests alike.
#pragma once

#include "raylab/camera.h"

namespace raylab::testkit {

// Camera's defaults (at the origin, looking down -z, +y up) with this size and vertical field
// of view in degrees.
inline Camera make_camera(int width, int height, float fov_y_degrees) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.fov_y_degrees = fov_y_degrees;
  return camera;
}

}  // namespace raylab::testkit
