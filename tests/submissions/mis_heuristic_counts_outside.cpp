// Grader self-test submission (stage 09b_mis): power_heuristic as n_f pdf_f^2 / (n_f pdf_f^2 +
// n_g pdf_g^2): the counts outside the squares, and infinity / infinity for a delta. Its paths are right.
#define MIS_VARIANT(v) v.counts_outside_square = true
#include "mis_variant.h"
