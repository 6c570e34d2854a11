// Grader self-test submission (stage 08_direct_light), broken: point_light_irradiance keeps a negative
// cos(theta) for a light behind the surface, where the irradiance is 0.
#define DIRECT_VARIANT(v) v.irradiance_behind_zero = false
#include "direct_variant.h"
