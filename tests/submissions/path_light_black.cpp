// Grader self-test submission (stage 09_path): GAMES101 pseudocode's shape, the emission of the
// camera ray's hit left out: the light is black when seen directly. The furnaces fit a / (1 - a).
#define PATH_VARIANT(v) v.emission_at_camera_hit = false
#include "path_variant.h"
