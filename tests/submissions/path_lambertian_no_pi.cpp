// Grader self-test submission (stage 09_path): each diffuse bounce weighed with f = albedo, 1 / pi
// missing (the direct light, stage 08's estimator, stays right). With roulette (p = 0.5) each
// bounce weighs pi a / p = 3.14, so the furnace's mean diverges (thousands instead of 2) and its
// pixels reach millions: a t-test alone let FurnaceWithRoulette pass, since the standard error was
// as huge as the mean. Its spread test must fail it, and the furnaces' fit names the missing 1 / pi.
#define PATH_VARIANT(v) v.f_is_albedo = true
#include "path_variant.h"
