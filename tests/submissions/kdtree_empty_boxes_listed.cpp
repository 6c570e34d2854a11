// Grader self-test submission (stage 05d_kdtree): primitives with an empty box go into the tree too: a lone one is listed in the root leaf.
#define KDTREE_VARIANT(v) (v.empty_boxes_listed = true)
#include "kdtree_variant.h"
