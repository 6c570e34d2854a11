// Grader self-test submission (stage 08_direct_light), broken: no test for an empty light list; the
// estimator chooses a light from none (LightSet::choose requires !empty(): it reads past the list).
#define DIRECT_VARIANT(v) v.check_no_lights = false
#include "direct_variant.h"
