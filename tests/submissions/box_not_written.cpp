// Grader self-test submission (stage 04_box): the stub as handed out. Stage 04 is not attempted;
// stage 05's traversal calls intersect_ray_box, so its tests that traverse are blocked by stage 04
// (the table, the test and the "next:" line say so), and its build tests are graded as usual.
#include "../../assignments/04_box/box.cpp"
