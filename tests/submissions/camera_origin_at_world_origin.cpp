// Grader self-test submission (stage 01_camera_rays), broken: every ray starts at the world's origin,
// not at camera.position (right only for a camera placed there).
#define CAMERA_VARIANT(v) v.origin_at_position = false
#include "camera_variant.h"
