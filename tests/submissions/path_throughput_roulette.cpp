// Grader self-test submission (stage 09_path), correct: Russian roulette with a probability of its
// own, the throughput's largest channel (divided by, as it must be). Expected: full marks.
#define PATH_VARIANT(v) v.throughput_roulette = true
#include "path_variant.h"
