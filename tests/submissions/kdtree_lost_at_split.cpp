// Grader self-test submission (stage 05d_kdtree): a primitive whose box crosses a plane goes only to
// the side of its box's centre: lost on the other side.
#define KDTREE_VARIANT(v) (v.lost_at_split = true)
#include "kdtree_variant.h"
