// Grader self-test submission (stage 09_path): still the stub, every other stage the reference.
// Stage 09 is not attempted; every other stage keeps full marks.
#include "../../assignments/09_path/path.cpp"
