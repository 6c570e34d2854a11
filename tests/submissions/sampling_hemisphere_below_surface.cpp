// Grader self-test submission (stage 07_sampling): the uniform hemisphere drawn with the sphere's
// z = 1 - 2u: half of the directions are below the surface.
// The reference file is included with this function renamed, so only it differs.
#define sample_uniform_hemisphere honest_sample_uniform_hemisphere
#include "../../solutions/07_sampling/sampling.cpp"
#undef sample_uniform_hemisphere

namespace raylab {

glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random);

glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random) {
  const float z = 1.0f - 2.0f * uniform_random.x;  // the mistake: the sphere's z
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * uniform_random.y;
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

}  // namespace raylab
