// Grader self-test submission (stage 07_sampling): the uniform sphere's pdf is 1 / (2 pi), twice the
// density (not normalised).
// The reference file is included with this function renamed, so only it differs.
#define uniform_sphere_pdf honest_uniform_sphere_pdf
#include "../../solutions/07_sampling/sampling.cpp"
#undef uniform_sphere_pdf

namespace raylab {

float uniform_sphere_pdf(const glm::vec3& direction);

float uniform_sphere_pdf(const glm::vec3& direction) {
  (void)direction;  // the same for every direction
  return 1.0f / (2.0f * kPi);  // the mistake: the sphere's solid angle is 4 pi
}

}  // namespace raylab
