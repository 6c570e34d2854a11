// Grader self-test submission (stage 09_path): divides by bsdf_pdf(...) instead of the sample's
// pdf; bsdf_pdf is 0 for mirrors and glass, so the specular Cornell box gets NaN and infinity.
#define PATH_VARIANT(v) v.pdf_from_bsdf_pdf = true
#include "path_variant.h"
