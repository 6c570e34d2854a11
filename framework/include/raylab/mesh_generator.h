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

}  // namespace raylab
