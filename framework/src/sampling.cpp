#include "raylab/sampling.h"

#include <cmath>

namespace raylab {

Frame::Frame(const glm::vec3& unit_normal) : normal(unit_normal) {
  const float sign = std::copysign(1.0f, unit_normal.z);
  const float a = -1.0f / (sign + unit_normal.z);
  const float b = unit_normal.x * unit_normal.y * a;
  tangent = glm::vec3(1.0f + sign * unit_normal.x * unit_normal.x * a, sign * b, -sign * unit_normal.x);
  bitangent = glm::vec3(b, sign + unit_normal.y * unit_normal.y * a, -unit_normal.y);
}

}  // namespace raylab
