// Grader self-test submission (stage 07_sampling): six mistakes at once, one per function, each named:
// the concentric disk map without its zero check (0 / 0 = NaN at the centre), the disk's pdf with
// the Jacobian r, the sphere with theta uniform (crowding the poles), the triangle's pdf returning
// the area, cosine samples uniform over the hemisphere, the uniform hemisphere's pdf cosine-weighted.
// The reference file is included with these functions renamed, so only they differ.
#define uniform_hemisphere_pdf honest_uniform_hemisphere_pdf
#define sample_cosine_hemisphere honest_sample_cosine_hemisphere
#define sample_uniform_sphere honest_sample_uniform_sphere
#define sample_uniform_disk honest_sample_uniform_disk
#define uniform_disk_pdf honest_uniform_disk_pdf
#define uniform_triangle_pdf honest_uniform_triangle_pdf
#include "../../solutions/07_sampling/sampling.cpp"
#undef uniform_hemisphere_pdf
#undef sample_cosine_hemisphere
#undef sample_uniform_sphere
#undef sample_uniform_disk
#undef uniform_disk_pdf
#undef uniform_triangle_pdf

namespace raylab {

float uniform_hemisphere_pdf(const glm::vec3& direction);
glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random);
glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random);
glm::vec2 sample_uniform_disk(glm::vec2 uniform_random);
float uniform_disk_pdf(glm::vec2 point);
float uniform_triangle_pdf(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2);

float uniform_hemisphere_pdf(const glm::vec3& direction) {
  return direction.z >= 0.0f ? direction.z / kPi : 0.0f;  // the mistake: the cosine-weighted density
}

glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random) {
  const float z = uniform_random.x;  // the mistake: z uniform is the uniform hemisphere
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * uniform_random.y;
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random) {
  const float z = std::cos(kPi * uniform_random.x);  // the mistake: theta uniform
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * uniform_random.y;
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

glm::vec2 sample_uniform_disk(glm::vec2 uniform_random) {
  // The concentric map without its check of the centre: the mistake, 0 / 0 = NaN there.
  const glm::vec2 offset = 2.0f * uniform_random - glm::vec2(1.0f);  // [-1, 1)^2
  float radius, angle;
  if (std::fabs(offset.x) > std::fabs(offset.y)) {
    radius = offset.x;
    angle = (kPi / 4.0f) * (offset.y / offset.x);
  } else {
    radius = offset.y;
    angle = kPi / 2.0f - (kPi / 4.0f) * (offset.x / offset.y);
  }
  return radius * glm::vec2(std::cos(angle), std::sin(angle));
}

float uniform_disk_pdf(glm::vec2 point) { return glm::length(point) / kPi; }  // the mistake: the Jacobian r

float uniform_triangle_pdf(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  const float twice_area = glm::length(glm::cross(p1 - p0, p2 - p0));
  return 0.5f * twice_area;  // the mistake: the area, not 1 / area
}

}  // namespace raylab
