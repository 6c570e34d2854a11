// raylab-make-mesh: writes the benchmark's generated mesh as an OBJ, to look at it or to render
// it in a scene. The bench itself makes the mesh in memory; no file is needed.
//
//   raylab-make-mesh TRIANGLES OUTPUT.obj [SEED]
//
// TRIANGLES is rounded to the nearest 12 n^2 (make_displaced_sphere, raylab/mesh_generator.h);
// the same arguments give the same file on every machine.
#include "raylab/mesh_generator.h"

#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: raylab-make-mesh TRIANGLES OUTPUT.obj [SEED]\n");
    return 1;
  }
  char* end = nullptr;
  const unsigned long triangles = std::strtoul(argv[1], &end, 10);
  if (*end != '\0' || triangles < 12 || triangles > 100000000ul) {
    std::fprintf(stderr, "raylab-make-mesh: TRIANGLES must be a whole number in 12..100000000, got '%s'\n", argv[1]);
    return 1;
  }
  const unsigned long seed = argc == 4 ? std::strtoul(argv[3], nullptr, 10) : 1ul;
  const raylab::TriangleMesh mesh =
      raylab::make_displaced_sphere(static_cast<std::uint32_t>(triangles), 1.0f, static_cast<std::uint32_t>(seed));
  std::FILE* out = std::fopen(argv[2], "w");
  if (!out) {
    std::fprintf(stderr, "raylab-make-mesh: cannot write %s\n", argv[2]);
    return 1;
  }
  std::fprintf(out, "# %s, seed %lu, written by raylab-make-mesh\n", mesh.name.c_str(), seed);
  for (const glm::vec3& p : mesh.positions) std::fprintf(out, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3)
    std::fprintf(out, "f %u %u %u\n", mesh.indices[i] + 1, mesh.indices[i + 1] + 1, mesh.indices[i + 2] + 1);
  const bool ok = std::fclose(out) == 0;
  if (!ok) std::fprintf(stderr, "raylab-make-mesh: error writing %s\n", argv[2]);
  std::fprintf(stderr, "%s -> %s\n", mesh.name.c_str(), argv[2]);
  return ok ? 0 : 1;
}
