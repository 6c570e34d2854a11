// Grader self-test submission (stage 05d_kdtree): stats.nodes_visited is never incremented.
#define KDTREE_VARIANT(v) (v.nodes_not_counted = true)
#include "kdtree_variant.h"
