// Grader self-test submission (stage 10_microfacet): two mistakes at once in f, no masking and
// Schlick's Fresnel at the normal's cosine wi.z instead of dot(wi, h). Only MicrofacetF loses.
#define MICROFACET_VARIANT(v) (v.f_no_masking = true, v.f_fresnel_at_normal = true)
#include "microfacet_variant.h"
