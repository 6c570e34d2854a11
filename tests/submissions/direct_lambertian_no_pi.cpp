// Grader self-test submission (stage 08_direct_light): f = albedo, 1 / pi missing. Stage 08 names
// it, and stage 09, whose diffuse surfaces use this f, names it too (its furnaces fit pi a).
#define DIRECT_VARIANT(v) v.lambertian_pi = false
#include "direct_variant.h"
