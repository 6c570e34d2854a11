// Grader self-test submission (stage 09b_mis), correct: the power heuristic written as
// 1 / (1 + (g / f)^2), and the light densities summed light by light. Expected: full marks.
#define MIS_VARIANT(v) v.ratio_form = true
#include "mis_variant.h"
