// Grader self-test submission (stage 08_direct_light): the intensity as power / pi, as if the
// power left through pi steradians instead of the whole sphere's 4 pi.
#define DIRECT_VARIANT(v) v.intensity_over_pi = true
#include "direct_variant.h"
