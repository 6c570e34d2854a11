// Grader self-test submission (stage 06_robustness): a triangle without area (its corners equal or
// on a line), or one the ray runs parallel to, is hit where the ray passes nearest its first
// corner, instead of being missed.
// Only the test of degenerate inputs fails, with its hint.
#define WATERTIGHT_VARIANT(v) v.degenerate_hits = true
#include "watertight_variant.h"
