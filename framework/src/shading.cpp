#include "raylab/shading.h"

#include <algorithm>
#include <cmath>

namespace raylab {

glm::vec3 refract(const glm::vec3& incident, const glm::vec3& normal, float ior) {
  float cos_incident = std::clamp(glm::dot(incident, normal), -1.0f, 1.0f);
  float eta_incident = 1.0f, eta_transmitted = ior;
  glm::vec3 n = normal;
  if (cos_incident < 0.0f) {
    cos_incident = -cos_incident;  // entering: the normal faces the incoming ray
  } else {
    std::swap(eta_incident, eta_transmitted);  // leaving the object
    n = -normal;
  }
  const float eta = eta_incident / eta_transmitted;
  const float k = 1.0f - eta * eta * (1.0f - cos_incident * cos_incident);
  if (k < 0.0f) return glm::vec3(0.0f);  // total internal reflection
  return eta * incident + (eta * cos_incident - std::sqrt(k)) * n;
}

float fresnel_reflectance(const glm::vec3& incident, const glm::vec3& normal, float ior) {
  float cos_incident = std::clamp(glm::dot(incident, normal), -1.0f, 1.0f);
  float eta_incident = 1.0f, eta_transmitted = ior;
  if (cos_incident > 0.0f) std::swap(eta_incident, eta_transmitted);
  const float sin_transmitted =
      eta_incident / eta_transmitted * std::sqrt(std::max(0.0f, 1.0f - cos_incident * cos_incident));
  if (sin_transmitted >= 1.0f) return 1.0f;  // total internal reflection
  const float cos_transmitted = std::sqrt(std::max(0.0f, 1.0f - sin_transmitted * sin_transmitted));
  cos_incident = std::fabs(cos_incident);
  const float r_s = (eta_transmitted * cos_incident - eta_incident * cos_transmitted) /
                    (eta_transmitted * cos_incident + eta_incident * cos_transmitted);
  const float r_p = (eta_incident * cos_incident - eta_transmitted * cos_transmitted) /
                    (eta_incident * cos_incident + eta_transmitted * cos_transmitted);
  return 0.5f * (r_s * r_s + r_p * r_p);
}

glm::vec3 offset_ray_origin(const SurfaceHit& hit, const glm::vec3& direction) {
  const glm::vec3& n = hit.geometric_normal;
  const float distance = glm::dot(glm::abs(n), hit.point_error);
  glm::vec3 offset = distance * n;
  if (glm::dot(direction, n) < 0.0f) offset = -offset;
  glm::vec3 origin = hit.point + offset;
  // Round away from the surface so that the offset survives the addition's rounding.
  for (int axis = 0; axis < 3; ++axis) {
    if (offset[axis] > 0.0f) origin[axis] = next_float_up(origin[axis]);
    else if (offset[axis] < 0.0f) origin[axis] = next_float_down(origin[axis]);
  }
  return origin;
}

ShadingStats& ShadingStats::operator+=(const ShadingStats& other) {
  camera_rays += other.camera_rays;
  reflection_rays += other.reflection_rays;
  refraction_rays += other.refraction_rays;
  shadow_rays += other.shadow_rays;
  rays_outside_bounds += other.rays_outside_bounds;
  return *this;
}

}  // namespace raylab
