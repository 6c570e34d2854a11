// The local frame that direction warps work in. The warps themselves, each with its density,
// are stage 07_sampling's functions (raylab/stages/07_sampling.h): the BSDFs and lights call
// those, so a student's warps are what the renderer samples with.
#pragma once

#include "raylab/math.h"

namespace raylab {

// An orthonormal basis around unit `normal` (Duff et al., "Building an Orthonormal Basis,
// Revisited", 2017): tangent, bitangent, normal, right-handed. A local direction (x, y, z) of
// stage 07 (z along the normal) is to_world(local) in the world.
struct Frame {
  glm::vec3 tangent, bitangent, normal;

  explicit Frame(const glm::vec3& unit_normal);
  glm::vec3 to_world(const glm::vec3& local) const { return local.x * tangent + local.y * bitangent + local.z * normal; }
  glm::vec3 to_local(const glm::vec3& world) const {
    return {glm::dot(world, tangent), glm::dot(world, bitangent), glm::dot(world, normal)};
  }
};

}  // namespace raylab
