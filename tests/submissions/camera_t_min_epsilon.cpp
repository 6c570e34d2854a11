// Grader self-test submission (stage 01_camera_rays), broken: t_min set to an epsilon of its own,
// 1e-3, where the contract says to leave the Ray's defaults (t_min = 0).
#define CAMERA_VARIANT(v) v.t_min = 1e-3f
#include "camera_variant.h"
