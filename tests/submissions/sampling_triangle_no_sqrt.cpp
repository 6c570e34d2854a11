// Grader self-test submission (stage 07_sampling): b1 + b2 drawn uniformly (a square root missing): the
// points crowd the vertex p0.
// The reference file is included with this function renamed, so only it differs.
#define sample_uniform_triangle honest_sample_uniform_triangle
#include "../../solutions/07_sampling/sampling.cpp"
#undef sample_uniform_triangle

namespace raylab {

Barycentrics sample_uniform_triangle(glm::vec2 uniform_random);

Barycentrics sample_uniform_triangle(glm::vec2 uniform_random) {
  const float root = uniform_random.x;  // the mistake: std::sqrt(uniform_random.x)
  return Barycentrics{root * (1.0f - uniform_random.y), root * uniform_random.y};
}

}  // namespace raylab
