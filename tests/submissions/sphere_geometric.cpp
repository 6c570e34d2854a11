// Grader self-test submission (stage 02_sphere): CORRECT, but the geometric method (closest approach to the centre) in double
#include "raylab/stages/02_sphere.h"

#include <cmath>

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  const glm::dvec3 d = glm::normalize(glm::dvec3(ray.direction));
  const double length = glm::length(glm::dvec3(ray.direction));
  const glm::dvec3 origin_to_center = glm::dvec3(sphere_center) - glm::dvec3(ray.origin);
  const double t_closest = glm::dot(origin_to_center, d);  // along the unit direction
  const glm::dvec3 closest = glm::dvec3(ray.origin) + t_closest * d;
  const double distance2 = glm::dot(closest - glm::dvec3(sphere_center), closest - glm::dvec3(sphere_center));
  const double radius2 = double(sphere_radius) * sphere_radius;
  if (distance2 > radius2) return std::nullopt;
  const double half_chord = std::sqrt(radius2 - distance2);
  for (const double t_unit : {t_closest - half_chord, t_closest + half_chord}) {
    const float t = static_cast<float>(t_unit / length);
    if (t > ray.t_min && t < ray.t_max) return t;
  }
  return std::nullopt;
}

}  // namespace raylab
