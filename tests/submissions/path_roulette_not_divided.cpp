// Grader self-test submission (stage 09_path): Russian roulette without the division by p.
// The furnaces fit 1 / (1 - a p), and the hint says so.
#define PATH_VARIANT(v) v.divide_by_roulette = false
#include "path_variant.h"
