// Grader self-test submission (stage 09_path): each bounce's direction from rand(), not from
// sampler.get_2d(). Unbiased, so the furnaces' means and the Cornell boxes pass; only the small
// Cornell box rendered twice with the same seed differs (SameSeedSamePicture), naming rand().
#define PATH_VARIANT(v) v.own_random_numbers = true
#include "path_variant.h"
