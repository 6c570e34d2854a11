// Grader self-test submission (stage 05d_kdtree): tree.bounds grown by 0.01 on every side: not the union of the boxes.
#define KDTREE_VARIANT(v) (v.bounds_padded = true)
#include "kdtree_variant.h"
