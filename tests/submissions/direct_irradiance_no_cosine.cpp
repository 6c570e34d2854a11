// Grader self-test submission (stage 08_direct_light): the irradiance I / d^2, the cosine missing.
#define DIRECT_VARIANT(v) v.irradiance_cosine = false
#include "direct_variant.h"
