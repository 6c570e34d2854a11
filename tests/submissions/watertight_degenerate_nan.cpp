// Grader self-test submission (stage 03b_watertight, graded at 06_robustness), broken:
// a triangle without area divides by its zero determinant and returns NaN.
#define WATERTIGHT_VARIANT(v) v.degenerate_gives_nan = true
#include "watertight_variant.h"
