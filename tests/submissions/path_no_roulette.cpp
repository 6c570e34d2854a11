// Grader self-test submission (stage 09_path), broken: no Russian roulette; every path goes on to
// context.max_depth. Unbiased (the furnaces' means are right), but against the contract, and
// without the roulette's noise: the furnaces with roulette fail their test of short paths.
#define PATH_VARIANT(v) v.play_roulette = false
#include "path_variant.h"
