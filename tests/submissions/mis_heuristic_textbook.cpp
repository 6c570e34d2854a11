// Grader self-test submission (stage 09b_mis): power_heuristic as pdf_f^2 / (pdf_f^2 + pdf_g^2): the
// counts ignored and 0 / 0 when both densities are 0. Its paths (counts 1, densities > 0) are right.
#define MIS_VARIANT(v) v.textbook_heuristic = true
#include "mis_variant.h"
