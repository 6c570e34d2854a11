// Grader self-test submission (stage 09_path): the path tracer computes the direct light itself (as
// GAMES101's castRay does) and its shadow ray runs the whole way to the light's point and past it
// (a unit direction, t_max = infinity): an area light is scene geometry, so the ray hits the light
// itself and no surface gets any direct light. Every furnace pixel is exactly 1, the emission the
// camera sees.
#define PATH_VARIANT(v) v.shadow_ray_hits_light = true
#include "path_variant.h"
