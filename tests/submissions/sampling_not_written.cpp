// Grader self-test submission (stage 07_sampling): still the stub, every other stage the
// reference. Stage 07 is not attempted, and every other stage keeps full marks: their pictures
// render with the Whitted integrator, which needs no warp.
#include "../../assignments/07_sampling/sampling.cpp"
