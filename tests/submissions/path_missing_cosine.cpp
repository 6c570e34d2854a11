// Grader self-test submission (stage 09_path): the bounce weight f / pdf, without the cosine.
// The furnaces fit a bounce weight of 2 a.
#define PATH_VARIANT(v) v.cosine = false
#include "path_variant.h"
