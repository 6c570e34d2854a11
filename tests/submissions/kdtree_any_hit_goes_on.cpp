// Grader self-test submission (stage 05d_kdtree): with any_hit, the walk searches on for the closest
// hit: right answers, more work than any_hit allows.
#define KDTREE_VARIANT(v) (v.any_hit_goes_on = true)
#include "kdtree_variant.h"
