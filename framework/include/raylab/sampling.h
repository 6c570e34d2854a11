// The local frame that direction warps work in. The warps themselves, each with its density,
// are stage 07_sampling's functions (raylab/stages/07_sampling.h): the BSDFs and lights call
// those, so a student's warps are what the renderer samples with.
#pragma once

#include "raylab/math.h"

#include <cmath>

namespace raylab {

// An orthonormal basis around unit `normal` (Duff et al., "Building an Orthonormal Basis,
// Revisited", 2017): tangent, bitangent, normal, right-handed. A local direction (x, y, z) of
// stage 07 (z along the normal) is to_world(local) in the world.
struct Frame {
  glm::vec3 tangent, bitangent, normal;

  // Inline, so that the basis stays in registers where it is used: made by a call, it came back
  // through memory in pieces that the loads after it could not take straight from the stores
  // (docs/performance.md, "Stores read back whole").
  explicit Frame(const glm::vec3& unit_normal) : normal(unit_normal) {
    const float sign = std::copysign(1.0f, unit_normal.z);
    const float a = -1.0f / (sign + unit_normal.z);
    const float b = unit_normal.x * unit_normal.y * a;
    tangent = glm::vec3(1.0f + sign * unit_normal.x * unit_normal.x * a, sign * b, -sign * unit_normal.x);
    bitangent = glm::vec3(b, sign + unit_normal.y * unit_normal.y * a, -unit_normal.y);
  }
  glm::vec3 to_world(const glm::vec3& local) const { return local.x * tangent + local.y * bitangent + local.z * normal; }
  glm::vec3 to_local(const glm::vec3& world) const {
    return {glm::dot(world, tangent), glm::dot(world, bitangent), glm::dot(world, normal)};
  }
};

}  // namespace raylab
