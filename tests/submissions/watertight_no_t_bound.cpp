// Grader self-test submission (stage 03b_watertight): the reference watertight test without
// the t error bound (delta_t). No leaks, the same answers as stage 03; but a ray leaving a
// large triangle can hit it again at a tiny t: shadow acne, which 06_robustness must see.
// The reference file is included with every rounding-error term gamma_bound(n) set to 0, so
// that its bound on the error of t is 0: only t_hit > 0 remains, which t_min already asks.
// (The headers come first, so that the macro reaches only the reference's own code.)
#include "raylab/math.h"
#include "raylab/stages/03b_watertight.h"

#define gamma_bound(n) 0.0f  // MISTAKE: no bound on the rounding error of t
#include "../../solutions/03b_watertight/watertight.cpp"
#undef gamma_bound
