// Grader self-test submission (stage 09_path), correct: diffuse bounces sampled uniformly over the
// hemisphere (pdf 1 / (2 pi)): more noise, the same expectation. Expected: full marks.
#define PATH_VARIANT(v) v.uniform_hemisphere = true
#include "path_variant.h"
