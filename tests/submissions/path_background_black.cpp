// Grader self-test submission (stage 09_path): black where the ray hits nothing, not the scene's
// background. Every graded picture has a black background, so only the probe that looks away from
// the Cornell box with a blue-grey background fails (BackgroundWhereNothingIsHit).
#define PATH_VARIANT(v) v.background = false
#include "path_variant.h"
