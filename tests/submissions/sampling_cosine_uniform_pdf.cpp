// Grader self-test submission (stage 07_sampling): cosine-weighted samples, but the uniform hemisphere's
// density as their pdf.
// The reference file is included with this function renamed, so only it differs.
#define cosine_hemisphere_pdf honest_cosine_hemisphere_pdf
#include "../../solutions/07_sampling/sampling.cpp"
#undef cosine_hemisphere_pdf

namespace raylab {

float cosine_hemisphere_pdf(const glm::vec3& direction);

float cosine_hemisphere_pdf(const glm::vec3& direction) {
  return direction.z > 0.0f ? 1.0f / (2.0f * kPi) : 0.0f;  // the mistake: the uniform hemisphere's density
}

}  // namespace raylab
