// Grader self-test submission (stage 09b_mis): power_heuristic computes the balance heuristic
// p_f / (p_f + p_g), and the path weighs with it: unbiased, but not the power heuristic.
#define MIS_VARIANT(v) v.balance = true
#include "mis_variant.h"
