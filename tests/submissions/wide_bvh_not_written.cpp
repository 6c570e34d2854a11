// Grader self-test submission (stage 05c_wide_bvh): still the stub, every other stage the
// reference. Stage 05c is not attempted; no other stage uses it.
#include "../../assignments/05c_wide_bvh/wide_bvh.cpp"
