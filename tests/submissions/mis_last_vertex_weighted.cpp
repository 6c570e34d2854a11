// Grader self-test submission (stage 09b_mis): the light sample at the last vertex (depth ==
// max_depth) is weighted though no BSDF sample follows it.
#define MIS_VARIANT(v) v.last_vertex_weighted = true
#include "mis_variant.h"
