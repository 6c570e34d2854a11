// Grader self-test submission (stage 03b_watertight): still the stub, every other stage the
// reference. The bonus stage 06_robustness must grade what is written (the sphere and box
// tests) and mark only the watertight tests as not attempted.
#include "../../assignments/03b_watertight/watertight.cpp"
