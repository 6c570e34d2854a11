// Grader self-test submission (stage 08_direct_light): the shadow ray starts at the hit point
// itself, not at offset_ray_origin(hit, direction). A point on a surface of the scene, rounded to
// just behind it, sees that surface at a tiny t: shadow acne, black where the light is in view.
#define DIRECT_VARIANT(v) v.shadow_ray_offset = false
#include "direct_variant.h"
