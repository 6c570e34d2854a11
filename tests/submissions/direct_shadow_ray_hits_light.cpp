// Grader self-test submission (stage 08_direct_light): the shadow ray runs the whole way to the
// light's point and past it (a unit direction, t_max = infinity): an area light is scene geometry,
// so the ray hits the light itself and every estimate is black where the light is unblocked.
#define DIRECT_VARIANT(v) v.shadow_ray_stops = false
#include "direct_variant.h"
