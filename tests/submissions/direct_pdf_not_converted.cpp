// Grader self-test submission (stage 08_direct_light): the area pdf returned as it is, not turned
// into a density per steradian. Stage 08 names it, also in its estimator's tests (which sample
// area lights with it); stage 09 names the stage-08 function.
#define DIRECT_VARIANT(v) v.pdf_converted = false
#include "direct_variant.h"
