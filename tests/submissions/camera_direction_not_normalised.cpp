// Grader self-test submission (stage 01_camera_rays), broken: the direction through the image plane
// is returned without normalising it (its length is not 1 away from the picture's centre).
#define CAMERA_VARIANT(v) v.normalise_direction = false
#include "camera_variant.h"
