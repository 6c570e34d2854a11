// Grader self-test submission (stage 05d_kdtree): the build goes one level deeper than kdtree_max_depth allows.
#define KDTREE_VARIANT(v) (v.one_level_too_deep = true)
#include "kdtree_variant.h"
