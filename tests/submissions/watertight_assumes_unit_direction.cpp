// Grader self-test submission (stage 03b_watertight, graded at 06_robustness), broken:
// t measured along the normalised direction (a distance, not the parameter of origin + t * d).
#define WATERTIGHT_VARIANT(v) v.normalise_direction = true
#include "watertight_variant.h"
