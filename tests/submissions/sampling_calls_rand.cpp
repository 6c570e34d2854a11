// Grader self-test submission (stage 07_sampling): the sphere's azimuth from rand(), not from
// uniform_random.y. Its samples have the right density, so only the test that asks for the same
// numbers twice fails (UniformSphereSamplesInDomain), naming rand().
// The reference file is included with this function renamed, so only it differs.
#define sample_uniform_sphere honest_sample_uniform_sphere
#include "../../solutions/07_sampling/sampling.cpp"
#undef sample_uniform_sphere

#include <cstdlib>

namespace raylab {

glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random);

glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random) {
  const float z = 1.0f - 2.0f * uniform_random.x;
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * static_cast<float>(std::rand() / (RAND_MAX + 1.0));  // the mistake
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

}  // namespace raylab
