// Grader self-test submission (stage 03b_watertight, graded at 06_robustness), broken:
// hits beyond ray.t_max accepted.
#define WATERTIGHT_VARIANT(v) v.check_t_max = false
#include "watertight_variant.h"
