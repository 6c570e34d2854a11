// Grader self-test submission (stage 03b_watertight, graded at 06_robustness), broken:
// a triangle seen from its back (by its winding) is missed.
#define WATERTIGHT_VARIANT(v) v.cull_back_faces = true
#include "watertight_variant.h"
