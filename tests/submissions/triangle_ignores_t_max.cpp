// Grader self-test submission (stage 03_triangle), broken: hits beyond ray.t_max are accepted.
#define TRIANGLE_VARIANT(v) v.check_t_max = false
#include "triangle_variant.h"
