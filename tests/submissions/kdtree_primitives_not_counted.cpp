// Grader self-test submission (stage 05d_kdtree): stats.primitives_tested is never incremented.
#define KDTREE_VARIANT(v) (v.primitives_not_counted = true)
#include "kdtree_variant.h"
