// Grader self-test submission (stage 05d_kdtree): the SAH tries planes only at the primitives'
// centres (a BVH's habit), never at their boxes' faces: the planes never fall where a cluster ends,
// and the empty space between two clusters is never cut off.
#define KDTREE_VARIANT(v) (v.centroid_planes = true)
#include "kdtree_variant.h"
