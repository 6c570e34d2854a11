// Grader self-test submission (stage 07_sampling): the disk's radius drawn uniformly (r = u, a square
// root missing): the points crowd the centre. Only the disk's density tests may fail; the cosine
// hemisphere here (the reference's) lifts the reference's disk, not this one.
// The reference file is included with this function renamed, so only it differs.
#define sample_uniform_disk honest_sample_uniform_disk
#include "../../solutions/07_sampling/sampling.cpp"
#undef sample_uniform_disk

namespace raylab {

glm::vec2 sample_uniform_disk(glm::vec2 uniform_random);

glm::vec2 sample_uniform_disk(glm::vec2 uniform_random) {
  const float radius = uniform_random.x;  // the mistake: sqrt(uniform_random.x)
  const float phi = 2.0f * kPi * uniform_random.y;
  return radius * glm::vec2(std::cos(phi), std::sin(phi));
}

}  // namespace raylab
