// Grader self-test submission (stage 03b_watertight, graded at 06_robustness), broken:
// b1 and b2 exchanged (b1 is p1's weight).
#define WATERTIGHT_VARIANT(v) v.swap_barycentrics = true
#include "watertight_variant.h"
