// Grader self-test submission (stage 08_direct_light): no shadow ray: light passes through
// everything between the surface and the light.
#define DIRECT_VARIANT(v) v.shadow_ray = false
#include "direct_variant.h"
