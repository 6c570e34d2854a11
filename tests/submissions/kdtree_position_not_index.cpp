// Grader self-test submission (stage 05d_kdtree): a hit names its position in the leaf lists
// (i), not the primitive the test was called with (tree.primitive_indices[i]).
#define KDTREE_VARIANT(v) (v.position_not_index = true)
#include "kdtree_variant.h"
