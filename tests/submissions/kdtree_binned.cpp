// Grader self-test submission (stage 05d_kdtree): a correct implementation written another way: planes at 32
// evenly spaced bins per axis rather than at the boxes' faces, every plane priced by counting. Full marks.
#define KDTREE_VARIANT(v) (v.binned = true)
#include "kdtree_variant.h"
