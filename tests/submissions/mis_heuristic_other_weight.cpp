// Grader self-test submission (stage 09b_mis): power_heuristic returns the other strategy's weight,
// (n_g pdf_g)^2 / ((n_f pdf_f)^2 + (n_g pdf_g)^2), guarded for its own density infinite or 0. Its
// paths weigh their samples right (they do not call power_heuristic), so only the heuristic's
// values are wrong, the other density 0 among them (0, not 1).
#define MIS_VARIANT(v) v.other_weight = true
#include "mis_variant.h"
