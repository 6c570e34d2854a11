// Grader self-test submission (stage 01_camera_rays), broken: the camera always looks down -z
// (camera space's view direction), whatever camera.look_at says.
#define CAMERA_VARIANT(v) v.use_look_at = false
#include "camera_variant.h"
