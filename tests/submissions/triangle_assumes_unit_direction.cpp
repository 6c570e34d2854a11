// Grader self-test submission (stage 03_triangle), broken: normalises the ray's direction first, so
// t is the distance, not the parameter of origin + t * direction (wrong when |direction| != 1).
#define TRIANGLE_VARIANT(v) v.normalise_direction = true
#include "triangle_variant.h"
