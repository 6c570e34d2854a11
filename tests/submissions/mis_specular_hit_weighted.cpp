// Grader self-test submission (stage 09b_mis): the emission found after a mirror or glass bounce
// is weighted like a diffuse bounce's, against a light sample that a mirror never takes: the
// light's reflection loses part of its weight. The contract gives it weight 1.
#define MIS_VARIANT(v) v.specular_hit_weighted = true
#include "mis_variant.h"
