// Grader self-test submission (stage 09_path), broken: emission counted at the camera's hit only,
// never after a mirror or glass bounce (where no direct light was estimated), so the light seen
// in a mirror or through glass is black. The furnaces (no mirrors) pass; the specular box does not.
#define PATH_VARIANT(v) v.emission_after_specular = false
#include "path_variant.h"
