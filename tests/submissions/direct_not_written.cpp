// Grader self-test submission (stage 08_direct_light): still the stub, every other stage the
// reference. Stage 08 is not attempted; stage 09, which samples with it, loses its tests.
#include "../../assignments/08_direct_light/direct_light.cpp"
