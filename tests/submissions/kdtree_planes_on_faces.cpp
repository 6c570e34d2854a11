// Grader self-test submission (stage 05d_kdtree): the cell's own faces are candidate planes too: a plane
// on a face cuts nothing off, yet with the empty bonus it is priced as the cheapest.
#define KDTREE_VARIANT(v) (v.planes_on_faces = true)
#include "kdtree_variant.h"
