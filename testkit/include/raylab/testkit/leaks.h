// Closed test meshes and the leak count: rays from inside a closed mesh aimed exactly at its
// shared edges and vertices, each of which must hit some triangle. The autograder's stage
// 06_robustness (through the stage server, in batches) and the stress suite and kernel bench
// (calling a kernel in this process) count leaks with this one function.
#pragma once

#include "raylab/mesh_generator.h"
#include "raylab/random.h"
#include "raylab/ray.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/testkit/triangles.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace raylab::testkit {

// A closed mesh: every edge shared by exactly two triangles, outward winding.
struct ClosedMesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;  // 3 per triangle
  glm::vec3 inside{0.0f};              // a point well inside
  float inside_radius = 0.0f;          // a ball around `inside` that is inside too
  std::size_t triangle_count() const { return indices.size() / 3; }
};

// A generated closed mesh (raylab/mesh_generator.h) with its inner ball; the name is the
// generated mesh's.
ClosedMesh closed_mesh(TriangleMesh generated, const glm::vec3& inside, float inside_radius);
// An icosahedron subdivided `levels` times on a sphere (20 * 4^levels triangles); inner ball
// of half the radius.
ClosedMesh closed_icosphere(int levels, float radius, const glm::vec3& center);
// A cube whose faces are n x n grids of square pairs (12 n^2 triangles); inner ball of half
// the half size.
ClosedMesh closed_grid_cube(int n, float half_size, const glm::vec3& center);

// For each ray, whether it hits any of the triangles (indices into the mesh's triangles) in
// candidates[i]; any triangle of the mesh when `candidates` is empty.
using HitsAnyTriangle = std::function<std::vector<bool>(const std::vector<Ray>& rays,
                                                        const std::vector<std::vector<std::uint32_t>>& candidates)>;

// The same for a triangle test in this process, stopping at each ray's first hit (the mesh
// must outlive the function).
HitsAnyTriangle hits_any_triangle_by(const ClosedMesh& mesh, TriangleFunction function);

struct LeakCount {
  std::uint64_t rays = 0, leaks = 0;
  std::optional<Ray> first_leak;
  double per_million() const { return rays ? 1e6 * double(leaks) / double(rays) : 0.0; }
};

// `rays` rays from `random`: each aims at a random edge of a random triangle, at a point on it
// (a float lerp of its ends, even-numbered rays) or exactly at its first vertex (odd ones),
// from a random point of the mesh's inner ball (up to 0.9 of its radius). A ray leaks when it
// hits no triangle: each is tried against the triangles around its edge's two vertices first,
// and only if it hits none of them against every triangle, so that the count is exact. The
// rays go to `hits` in batches.
LeakCount count_leaks(const ClosedMesh& mesh, std::uint64_t rays, Pcg32& random, const HitsAnyTriangle& hits);

}  // namespace raylab::testkit
