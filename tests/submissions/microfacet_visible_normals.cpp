// Grader self-test submission (stage 10_microfacet): sample_microfacet_wi mirrors wo about a
// visible normal (Heitz's sampling, a better sampler the contract rules out, since microfacet_pdf
// is the density of sample_ggx_half_vector's half vectors). Only the wi samples' test fails, and
// it names the visible normals; from wo along the normal both densities are the same.
#define MICROFACET_VARIANT(v) (v.wi_visible_normals = true)
#include "microfacet_variant.h"
