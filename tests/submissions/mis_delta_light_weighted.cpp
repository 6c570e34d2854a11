// Grader self-test submission (stage 09b_mis): a point light's sample is weighted by the power
// heuristic (its pdf 1 against the BSDF's) instead of keeping weight 1.
#define MIS_VARIANT(v) v.delta_weighted = true
#include "mis_variant.h"
