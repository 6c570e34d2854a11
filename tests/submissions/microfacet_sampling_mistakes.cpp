// Grader self-test submission (stage 10_microfacet): half vectors with tan(theta) = alpha u / (1 - u),
// the square root missing, and microfacet_pdf without the Jacobian 1 / (4 |wo . h|). The half
// vectors' test names the square root, the wi samples' test the half vectors it is built on, and
// the density's test the Jacobian.
#define MICROFACET_VARIANT(v) (v.half_vector_no_sqrt = true, v.pdf_no_jacobian = true)
#include "microfacet_variant.h"
