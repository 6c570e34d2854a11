// Grader self-test submission (stage 09b_mis): the path starts with previous_specular = false, so
// the emission the camera sees directly is weighted as if a BSDF sample had found it, with a BSDF
// density of 0: it counts 0. The contract gives it weight 1 (only one strategy makes that path).
#define MIS_VARIANT(v) v.camera_hit_weighted = true
#include "mis_variant.h"
