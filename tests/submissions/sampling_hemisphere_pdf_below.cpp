// Grader self-test submission (stage 07_sampling): uniform_hemisphere_pdf returns 1 / (2 pi) for every
// direction, also below the surface (z < 0), where the warp never goes and the density is 0.
// The reference file is included with this function renamed, so only it differs.
#define uniform_hemisphere_pdf honest_uniform_hemisphere_pdf
#include "../../solutions/07_sampling/sampling.cpp"
#undef uniform_hemisphere_pdf

namespace raylab {

float uniform_hemisphere_pdf(const glm::vec3& direction);

float uniform_hemisphere_pdf(const glm::vec3& direction) {
  (void)direction;
  return 1.0f / (2.0f * kPi);  // the mistake: no test of z
}

}  // namespace raylab
