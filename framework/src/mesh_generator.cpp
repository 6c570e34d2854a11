#include "raylab/mesh_generator.h"

#include <algorithm>
#include <cmath>

namespace raylab {
namespace {

// A small integer hash (deterministic everywhere) turned into a float in [0, 1).
float hash_unit(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return static_cast<float>(x >> 8) * (1.0f / 16777216.0f);
}

// Height over the unit direction: a few sinusoidal waves of rising frequency.
float displacement(const glm::vec3& direction, std::uint32_t seed) {
  constexpr int kWaves = 6;
  float height = 0.0f;
  float amplitude = 0.06f, frequency = 3.0f;
  for (int w = 0; w < kWaves; ++w) {
    const std::uint32_t key = seed * 97u + static_cast<std::uint32_t>(w) * 13u;
    const glm::vec3 axis = glm::normalize(glm::vec3(hash_unit(key) - 0.5f, hash_unit(key + 1) - 0.5f,
                                                    hash_unit(key + 2) - 0.5f) + glm::vec3(1e-3f));
    const float phase = 6.2831853f * hash_unit(key + 3);
    height += amplitude * std::sin(frequency * glm::dot(direction, axis) * 3.0f + phase);
    amplitude *= 0.6f;
    frequency *= 2.1f;
  }
  return height;
}

}  // namespace

TriangleMesh make_displaced_sphere(std::uint32_t triangle_count, float radius, std::uint32_t seed) {
  const auto n = static_cast<std::uint32_t>(
      std::max(1.0, std::round(std::sqrt(static_cast<double>(triangle_count) / 12.0))));
  TriangleMesh mesh;
  mesh.name = "displaced sphere (" + std::to_string(12ull * n * n) + " triangles)";
  // The six faces of the cube [-1, 1]^3: a normal axis, its sign, and the two in-face axes
  // chosen so that (u, v, normal) is right-handed (outward winding).
  struct Face {
    int normal_axis;
    float sign;
    int u_axis, v_axis;
  };
  const Face faces[6] = {{0, 1, 1, 2}, {0, -1, 2, 1}, {1, 1, 2, 0}, {1, -1, 0, 2}, {2, 1, 0, 1}, {2, -1, 1, 0}};
  const std::uint32_t side = n + 1;
  mesh.positions.reserve(6u * side * side);
  mesh.indices.reserve(36ull * n * n);
  for (const Face& face : faces) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (std::uint32_t j = 0; j <= n; ++j)
      for (std::uint32_t i = 0; i <= n; ++i) {
        glm::vec3 cube(0.0f);
        cube[face.normal_axis] = face.sign;
        cube[face.u_axis] = 2.0f * static_cast<float>(i) / static_cast<float>(n) - 1.0f;
        cube[face.v_axis] = 2.0f * static_cast<float>(j) / static_cast<float>(n) - 1.0f;
        const glm::vec3 direction = glm::normalize(cube);
        mesh.positions.push_back(radius * (1.0f + displacement(direction, seed)) * direction);
      }
    for (std::uint32_t j = 0; j < n; ++j)
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t a = base + j * side + i, b = a + 1, c = a + side, d = c + 1;
        mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
      }
  }
  return mesh;
}

}  // namespace raylab
