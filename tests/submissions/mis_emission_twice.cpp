// Grader self-test submission (stage 09b_mis): the emission a BSDF sample finds after a diffuse
// bounce is added with weight 1, while the light sample is weighted: the light counted twice.
#define MIS_VARIANT(v) v.emission_unweighted = true
#include "mis_variant.h"
