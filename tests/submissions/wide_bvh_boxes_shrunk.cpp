// Grader self-test submission (stage 05c_wide_bvh), broken:
// every slot's box shrunk by a tenth of its size on x: it no longer holds its child.
#define WIDE_BVH_VARIANT(v) v.boxes_shrunk = true
#include "wide_bvh_variant.h"
