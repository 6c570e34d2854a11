// Grader self-test submission (stage 09b_mis): still the stub, every other stage the reference.
// Stage 09b is not attempted; every other stage keeps full marks.
#include "../../assignments/09b_mis/mis.cpp"
