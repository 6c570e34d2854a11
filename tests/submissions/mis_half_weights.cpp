// Grader self-test submission (stage 09b_mis): power_heuristic right, but the path weighs both samples
// by 1/2 wherever both strategies can make it: unbiased (the weights add up to 1), but not the power
// heuristic, and no model of a common mistake explains it.
#define MIS_VARIANT(v) v.half_weights = true
#include "mis_variant.h"
