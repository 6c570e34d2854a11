// Grader self-test submission (stage 05c_wide_bvh): two mistakes in the four-box test, the slabs
// by min/max of the two planes with no mask (so the empty slots' boxes, +infinity to -infinity,
// are reported) and max(enter, 0 * infinity) taken as NaN (rays in a face plane lose the box).
// Both hints, and only the box test loses: the traversal looks only at the slots in use, and its
// rays do not start in a face plane.
#define WIDE_BVH_VARIANT(v) (v.min_max_slabs_unmasked = true, v.nan_loses_the_box = true)
#include "wide_bvh_variant.h"
