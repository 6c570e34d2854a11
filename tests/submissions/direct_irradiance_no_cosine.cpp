// Grader self-test submission (stage 08_direct_light): the irradiance I / d^2, the cosine missing.
#define point_light_irradiance reference_point_light_irradiance
#include "../../solutions/08_direct_light/direct_light.cpp"
#undef point_light_irradiance

namespace raylab {
glm::vec3 point_light_irradiance(const glm::vec3& intensity, const glm::vec3& light_position, const glm::vec3& point,
                                 const glm::vec3& normal) {
  const glm::vec3 to_light = light_position - point;
  if (glm::dot(normal, to_light) <= 0.0f) return glm::vec3(0.0f);
  return intensity / glm::dot(to_light, to_light);
}
}  // namespace raylab
