// Grader self-test submission (stage 08_direct_light): when sample_li gives no sample (a sphere
// light's far side), new numbers are drawn until one comes, instead of returning black. The
// samples kept then have another density than the pdf they are divided by: the estimate of the
// sphere light is too bright.
#define DIRECT_VARIANT(v) v.retry_without_sample = true
#include "direct_variant.h"
