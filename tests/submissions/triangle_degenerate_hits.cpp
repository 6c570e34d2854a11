// Grader self-test submission (stage 03_triangle): det == 0 (a ray parallel to the triangle's
// plane, or a triangle without area) taken as a hit where the ray passes nearest p0. A constructed
// mistake: Moller-Trumbore without its determinant test already rejects these inputs through NaN
// and infinity, so it shows that the test of degenerate inputs fails when the rule is broken.
#define TRIANGLE_VARIANT(v) v.degenerate_hits = true
#include "triangle_variant.h"
