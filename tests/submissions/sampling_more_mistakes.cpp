// Grader self-test submission (stage 07_sampling): five more mistakes, one per warp, each
// named: the uniform hemisphere cosine-weighted, the cosine hemisphere's directions not unit
// length, the sphere's directions only above z = 0, the disk's pdf of another shape (it
// integrates to 1), barycentrics that leave the triangle.
// The reference file is included with these functions renamed, so only they differ.
#define sample_uniform_hemisphere honest_sample_uniform_hemisphere
#define sample_cosine_hemisphere honest_sample_cosine_hemisphere
#define sample_uniform_sphere honest_sample_uniform_sphere
#define uniform_disk_pdf honest_uniform_disk_pdf
#define sample_uniform_triangle honest_sample_uniform_triangle
#include "../../solutions/07_sampling/sampling.cpp"
#undef sample_uniform_hemisphere
#undef sample_cosine_hemisphere
#undef sample_uniform_sphere
#undef uniform_disk_pdf
#undef sample_uniform_triangle

namespace raylab {

glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random);
glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random);
glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random);
float uniform_disk_pdf(glm::vec2 point);
Barycentrics sample_uniform_triangle(glm::vec2 uniform_random);

glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random) {
  const float z = std::sqrt(uniform_random.x);  // the mistake: cosine-weighted
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * uniform_random.y;
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random) {
  // Malley's method with the reference's disk, but not lifted onto the hemisphere.
  const glm::vec2 disk = sample_uniform_disk(uniform_random);
  return glm::vec3(disk.x, disk.y, 1.0f);  // the mistake: not normalised
}

glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random) {
  const float z = 1.0f - uniform_random.x;  // the mistake: only z > 0
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * uniform_random.y;
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

float uniform_disk_pdf(glm::vec2 point) {
  // the mistake: a density that integrates to 1 but is not the samples' one
  return glm::dot(point, point) <= 1.0f ? 2.0f * (1.0f - glm::dot(point, point)) / kPi : 0.0f;
}

Barycentrics sample_uniform_triangle(glm::vec2 uniform_random) {
  return Barycentrics{uniform_random.x, uniform_random.y};  // the mistake: b1 + b2 can exceed 1
}

}  // namespace raylab
