// Grader self-test submission (stage 05d_kdtree): the walk returns after the first leaf with a hit,
// even when the hit lies beyond that leaf's cell.
#define KDTREE_VARIANT(v) (v.hit_beyond_cell = true)
#include "kdtree_variant.h"
