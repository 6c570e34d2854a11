// Grader self-test submission (stage 08_direct_light), broken: the estimator weighs a light sample
// behind the surface with f = albedo / pi and |cos(theta)|, so a surface facing away from the light
// is lit through itself.
#define DIRECT_VARIANT(v) v.light_from_behind = true
#include "direct_variant.h"
