// Grader self-test submission (stage 05d_kdtree): the near child keeps its parent's interval end, so
// a hit beyond the plane is taken as inside the near cell.
#define KDTREE_VARIANT(v) (v.interval_not_cut = true)
#include "kdtree_variant.h"
