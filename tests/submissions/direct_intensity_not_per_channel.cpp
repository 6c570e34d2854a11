// Grader self-test submission (stage 08_direct_light), broken: point_light_intensity gives every
// channel the red channel's power / (4 pi): the contract's power is per channel.
#define DIRECT_VARIANT(v) v.intensity_grey = true
#include "direct_variant.h"
