// Grader self-test submission (stage 05d_kdtree): the walk goes through every cell the ray crosses:
// right answers, too much work.
#define KDTREE_VARIANT(v) (v.never_stops = true)
#include "kdtree_variant.h"
