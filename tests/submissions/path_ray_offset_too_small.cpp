// Grader self-test submission (stage 09_path): every bounce's ray starts 1e-5 off the surface
// along its normal (GAMES101 assignment 7's EPSILON), not with spawn_ray. In the furnace, a unit
// sphere, that clears the surface; in the Cornell box, whose coordinates reach 559, it is below
// their rounding error (about 3e-5), so rays hit the surface they leave again (acne). Expected:
// the furnaces pass, the boxes fail, and the hint names the ray's start, not the mirrors.
#define PATH_VARIANT(v) v.next_ray_offset = 1e-5f
#include "path_variant.h"
