// Grader self-test submission (stage 05_bvh): a correct median-split build written another
// way: sort the node's primitives by centroid along the longest axis of its box (std::sort,
// no tie-breaking) and split at the middle; nodes appended with push_back (no reserve) and
// referred to by index (bvh_sorted_build.h). Expected: full marks.
#define SORTED_BUILD_AXIS(box, depth) (box).longest_axis()
#include "bvh_sorted_build.h"
