// Grader self-test submission (stage 05c_wide_bvh), broken:
// intersect_ray_box4 exits at infinity, not at ray.t_max: bits for boxes beyond it.
#define WIDE_BVH_VARIANT(v) v.box4_ignores_t_max = true
#include "wide_bvh_variant.h"
