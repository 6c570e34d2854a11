// Warps from uniform random numbers in [0, 1)^2 to points and directions, each with its
// density: what BSDFs and lights sample with. (The Monte Carlo stages planned for the
// course have students write these; the framework's own versions live here.)
#pragma once

#include "raylab/math.h"

namespace raylab {

// An orthonormal basis around unit `normal` (Duff et al., "Building an Orthonormal Basis,
// Revisited", 2017): tangent, bitangent, normal, right-handed.
struct Frame {
  glm::vec3 tangent, bitangent, normal;

  explicit Frame(const glm::vec3& unit_normal);
  glm::vec3 to_world(const glm::vec3& local) const { return local.x * tangent + local.y * bitangent + local.z * normal; }
  glm::vec3 to_local(const glm::vec3& world) const {
    return {glm::dot(world, tangent), glm::dot(world, bitangent), glm::dot(world, normal)};
  }
};

// A point of the unit disk, uniform by area (density 1 / pi), by Shirley and Chiu's
// concentric map (strata of the square stay compact on the disk).
glm::vec2 sample_uniform_disk(glm::vec2 u);

// A direction of the hemisphere z > 0 with density cos(theta) / pi (Malley's method).
glm::vec3 sample_cosine_hemisphere(glm::vec2 u);
inline float cosine_hemisphere_pdf(float cos_theta) { return cos_theta > 0.0f ? cos_theta / kPi : 0.0f; }

// A direction of the unit sphere, uniform (density 1 / (4 pi)).
glm::vec3 sample_uniform_sphere(glm::vec2 u);

// Barycentrics (b1, b2) of a point uniform by area on a triangle: p = (1 - b1 - b2) p0 +
// b1 p1 + b2 p2 (the square-root warp, pbrt-v4 section A.5.5).
glm::vec2 sample_uniform_triangle(glm::vec2 u);

}  // namespace raylab
