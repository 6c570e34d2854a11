// Grader self-test submission (stage 09b_mis): two mistakes at once. power_heuristic computes the
// balance heuristic, and the BSDF sample's weight takes the light's density per unit area. Neither
// model alone explains the replayed paths; the pair does, and the hint names both.
#define MIS_VARIANT(v) (v.balance = true, v.area_pdf_in_bsdf_weight = true)
#include "mis_variant.h"
