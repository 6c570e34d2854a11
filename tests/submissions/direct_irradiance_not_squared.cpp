// Grader self-test submission (stage 08_direct_light), broken: point_light_irradiance divides by the
// distance, not its square: I cos(theta) / d.
#define DIRECT_VARIANT(v) v.irradiance_squared = false
#include "direct_variant.h"
