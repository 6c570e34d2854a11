// Grader self-test submission (stage 09_path): the throughput is never multiplied by the bounce
// weight f |cos| / pdf (only divided by the roulette probability). The furnaces fit a bounce
// weight of 1, which at albedo 0.5 is also what the missing cosine's 2 a gives: the low-albedo
// furnace tells them apart, so the hint must not say "the cosine is missing".
#define PATH_VARIANT(v) v.multiply_throughput = false
#include "path_variant.h"
