// Grader self-test submission (stage 09_path): the loop `for (depth = 0; depth < max_depth; ...)`,
// so the surface at depth == max_depth adds no emission and no direct light. The furnace without
// roulette (albedo 0.5, max depth 5) fits 1 + a + ... + a^5 instead of ... + a^6.
#define PATH_VARIANT(v) v.one_surface_short = true
#include "path_variant.h"
