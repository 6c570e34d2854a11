// Grader self-test submission (stage 05d_kdtree): still the stub, every other stage the reference.
// Stage 05d is not attempted; no other stage uses it.
#include "../../assignments/05d_kdtree/kdtree.cpp"
