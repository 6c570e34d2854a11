// Grader self-test submission (stage 05d_kdtree): a box that lies in the plane goes to neither side: lost.
#define KDTREE_VARIANT(v) (v.flat_dropped = true)
#include "kdtree_variant.h"
