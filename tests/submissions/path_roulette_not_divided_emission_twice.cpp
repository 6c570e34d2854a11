// Grader self-test submission (stage 09_path): two mistakes at once, Russian roulette's survivors
// not divided by p and emission counted again after diffuse bounces. No single mistake explains the
// furnaces; the pair does, and the hint names both.
#define PATH_VARIANT(v) v.divide_by_roulette = false, v.emission_after_diffuse = true
#include "path_variant.h"
