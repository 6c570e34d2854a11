// Grader self-test submission (stage 10_microfacet): still the stub, every other stage the
// reference. Stage 10 is not attempted; no other stage uses it.
#include "../../assignments/10_microfacet/microfacet.cpp"
