// Grader self-test submission (stage 03_triangle), broken: the interval's ends included (t >= t_min,
// t <= t_max), where the contract excludes both.
#define TRIANGLE_VARIANT(v) v.ends_included = true
#include "triangle_variant.h"
