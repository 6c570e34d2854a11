#include "raylab/mesh_generator.h"

#include "raylab/random.h"

#include <string>
#include <vector>
#include <utility>
#include <tuple>
#include <map>

#include <algorithm>
#include <cmath>

namespace raylab {
namespace {

// Height over the unit direction: a few sinusoidal waves of rising frequency.
float displacement(const glm::vec3& direction, std::uint32_t seed) {
  constexpr int kWaves = 6;
  float height = 0.0f;
  float amplitude = 0.06f, frequency = 3.0f;
  for (int w = 0; w < kWaves; ++w) {
    Pcg32 random(mix_bits(seed), static_cast<std::uint64_t>(w));  // each wave its own stream
    const float axis_x = random.next_float(), axis_y = random.next_float(), axis_z = random.next_float();
    const glm::vec3 axis = glm::normalize(glm::vec3(axis_x - 0.5f, axis_y - 0.5f, axis_z - 0.5f) + glm::vec3(1e-3f));
    const float phase = 6.2831853f * random.next_float();
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

TriangleMesh make_icosphere(int levels, float radius, const glm::vec3& center) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<glm::dvec3> points = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                    {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::uint32_t> faces = {0, 11, 5, 0, 5,  1,  0,  1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                      4, 11, 10, 2, 10, 7, 6,  7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                      6, 8,  3,  8, 9,  4, 9,  5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  for (glm::dvec3& p : points) p = glm::normalize(p);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;  // edge -> new vertex
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      points.push_back(glm::normalize(points[a] + points[b]));
      const auto index = static_cast<std::uint32_t>(points.size() - 1);
      midpoints[key] = index;
      return index;
    };
    std::vector<std::uint32_t> next;
    for (std::size_t f = 0; f < faces.size(); f += 3) {
      const std::uint32_t a = faces[f], b = faces[f + 1], c = faces[f + 2];
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    faces = std::move(next);
  }
  TriangleMesh mesh;
  mesh.name = "icosphere_" + std::to_string(faces.size() / 3);
  for (const glm::dvec3& p : points) mesh.positions.push_back(center + radius * glm::vec3(p));
  mesh.indices = std::move(faces);
  return mesh;
}

TriangleMesh make_grid_cube(int n, float half_size, const glm::vec3& center) {
  TriangleMesh mesh;
  std::map<std::tuple<int, int, int>, std::uint32_t> vertex_of;
  auto vertex = [&](int i, int j, int k) {  // integer lattice coordinates 0..n
    const auto key = std::make_tuple(i, j, k);
    const auto found = vertex_of.find(key);
    if (found != vertex_of.end()) return found->second;
    const glm::vec3 unit(2.0f * float(i) / float(n) - 1.0f, 2.0f * float(j) / float(n) - 1.0f,
                         2.0f * float(k) / float(n) - 1.0f);
    mesh.positions.push_back(center + half_size * unit);
    const auto index = static_cast<std::uint32_t>(mesh.positions.size() - 1);
    vertex_of[key] = index;
    return index;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side <= 1; ++side)
      for (int u = 0; u < n; ++u)
        for (int v = 0; v < n; ++v) {
          auto at = [&](int du, int dv) {
            int c[3];
            c[axis] = side * n;
            c[(axis + 1) % 3] = u + du;
            c[(axis + 2) % 3] = v + dv;
            return vertex(c[0], c[1], c[2]);
          };
          const std::uint32_t a = at(0, 0), b = at(1, 0), c = at(1, 1), d = at(0, 1);
          // (axis+1, axis+2) is right-handed around +axis: counter-clockwise seen from outside on side 1.
          if (side == 1) mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
          else mesh.indices.insert(mesh.indices.end(), {a, c, b, a, d, c});
        }
  mesh.name = "grid_cube_" + std::to_string(mesh.indices.size() / 3);
  return mesh;
}

}  // namespace raylab
