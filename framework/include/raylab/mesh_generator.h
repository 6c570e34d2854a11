// Large test meshes made on the fly, so that benchmarks need no big files: a finely
// tessellated, bumpy sphere. Deterministic: the same arguments give the same floats on every
// machine (only +, *, sqrt and a fixed sum of sines; no random engine).
#pragma once

#include "raylab/scene.h"

#include <cstdint>

namespace raylab {

// A displaced sphere of about `triangle_count` triangles (at least 12): a cube whose six
// faces are n x n grids (12 n^2 triangles, n = round(sqrt(triangle_count / 12))), each vertex
// pushed onto the sphere of radius `radius` around the origin and then moved along the normal
// by a sum of sines (bumps of up to about 15% of the radius, shaped by `seed`). Closed, no
// degenerate triangles, outward winding.
TriangleMesh make_displaced_sphere(std::uint32_t triangle_count, float radius = 1.0f,
                                   std::uint32_t seed = 1);

// Closed meshes whose every edge is shared by exactly two triangles (outward winding), for
// tests that shoot rays at shared edges and vertices (leaks through a closed mesh):
// an icosahedron subdivided `levels` times onto the sphere (20 * 4^levels triangles; the
// points are computed in double, then rounded once), and a cube whose faces are n x n grids
// of squares, two triangles each (12 n^2 triangles; neighbours in one plane share edges).
TriangleMesh make_icosphere(int levels, float radius, const glm::vec3& center);
TriangleMesh make_grid_cube(int n, float half_size, const glm::vec3& center);

}  // namespace raylab
