// Grader self-test submission (stage 05d_kdtree): two mistakes at once, one in each function: a
// primitive whose box crosses a plane goes only to the side of its box's centre (the build), and
// the near child keeps its parent's interval end (the walk). Each is named in its own test: the
// walk is graded on the grader's trees, so the lost primitives cost it nothing.
#define KDTREE_VARIANT(v) (v.lost_at_split = true, v.interval_not_cut = true)
#include "kdtree_variant.h"
