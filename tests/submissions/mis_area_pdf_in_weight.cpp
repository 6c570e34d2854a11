// Grader self-test submission (stage 09b_mis): the BSDF sample that hits a light is weighted against
// the light's density per unit area (GAMES101's 1 / area), not per steradian: biased.
#define MIS_VARIANT(v) v.area_pdf_in_bsdf_weight = true
#include "mis_variant.h"
