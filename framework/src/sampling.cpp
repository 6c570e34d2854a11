#include "raylab/sampling.h"

#include <algorithm>
#include <cmath>

namespace raylab {

Frame::Frame(const glm::vec3& unit_normal) : normal(unit_normal) {
  const float sign = std::copysign(1.0f, unit_normal.z);
  const float a = -1.0f / (sign + unit_normal.z);
  const float b = unit_normal.x * unit_normal.y * a;
  tangent = glm::vec3(1.0f + sign * unit_normal.x * unit_normal.x * a, sign * b, -sign * unit_normal.x);
  bitangent = glm::vec3(b, sign + unit_normal.y * unit_normal.y * a, -unit_normal.y);
}

glm::vec2 sample_uniform_disk(glm::vec2 u) {
  const glm::vec2 offset = 2.0f * u - glm::vec2(1.0f);  // [-1, 1)^2
  if (offset.x == 0.0f && offset.y == 0.0f) return glm::vec2(0.0f);
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

glm::vec3 sample_cosine_hemisphere(glm::vec2 u) {
  const glm::vec2 disk = sample_uniform_disk(u);
  const float z = std::sqrt(std::max(0.0f, 1.0f - disk.x * disk.x - disk.y * disk.y));
  return glm::vec3(disk.x, disk.y, z);
}

glm::vec3 sample_uniform_sphere(glm::vec2 u) {
  const float z = 1.0f - 2.0f * u.x;
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  return glm::vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

glm::vec2 sample_uniform_triangle(glm::vec2 u) {
  const float root = std::sqrt(u.x);
  return glm::vec2(root * (1.0f - u.y), root * u.y);  // (b1, b2); b0 = 1 - root
}

}  // namespace raylab
