// Grader self-test submission (stage 09_path): emission added at every hit, also after diffuse
// bounces whose light estimate_direct_light counted already. The furnaces fit (1 + a) / (1 - a).
#define PATH_VARIANT(v) v.emission_after_diffuse = true
#include "path_variant.h"
