// For tests/tools/check_gradescope.sh, Gradescope's limits: an intersect_ray_triangle that takes
// memory without end and writes to every page of it, as a real leak would (so the memory counts
// in the container, not only in the address space). Within the container's 768 MB the stage
// server's memory limit must stop it (std::bad_alloc: stage 03 loses its tests) before the
// container runs out, so no process of the run is killed for memory and the other stages keep
// their marks.
#include "raylab/stages/03_triangle.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  (void)ray;
  (void)p0;
  (void)p1;
  (void)p2;
  constexpr std::size_t kBlock = std::size_t{16} << 20;
  static std::vector<std::unique_ptr<char[]>> kept;  // never given back
  for (;;) {
    std::unique_ptr<char[]> block(new char[kBlock]);
    for (std::size_t i = 0; i < kBlock; i += 4096) static_cast<volatile char*>(block.get())[i] = 1;
    kept.push_back(std::move(block));
  }
}

}  // namespace raylab
