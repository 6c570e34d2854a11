// Self-test submission: an intersect_ray_triangle that asks for memory without end, as a
// container that grows in a loop would, and keeps all of it. The memory limit (RLIMIT_AS on
// Linux, the job object's committed memory on Windows) makes the allocation fail; the stage
// loses its tests with "ran out of memory", and the later stages (which never call it) keep
// their marks. It asks for the memory without touching it, so the test costs no real memory;
// the limit counts it all the same. If no limit stops it by 64 GiB, it gives everything back
// and answers as the reference does: then no "ran out of memory", and the self-test fails.
// On Windows it writes one byte to every page it gets, as a real container would: under Wine
// the grader's memory watch sees only memory that was written to (process_windows.cpp), and the
// Windows check runs it with a small limit so that this costs little real memory. There the
// stage loses its tests with "over the memory limit" (Wine) or "ran out of memory" (Windows).
#include "raylab/stages/03_triangle.h"

#include <cmath>
#include <memory>
#include <vector>

namespace raylab {
namespace {
std::optional<TriangleHit> honest_answer(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  const glm::vec3 edge1 = p1 - p0, edge2 = p2 - p0;
  const glm::vec3 pvec = glm::cross(ray.direction, edge2);
  const float determinant = glm::dot(edge1, pvec);
  if (!(determinant != 0.0f) || !std::isfinite(determinant)) return std::nullopt;
  const float inverse = 1.0f / determinant;
  const glm::vec3 tvec = ray.origin - p0;
  const float barycentric_b1 = glm::dot(tvec, pvec) * inverse;
  if (!(barycentric_b1 >= 0.0f && barycentric_b1 <= 1.0f)) return std::nullopt;
  const glm::vec3 qvec = glm::cross(tvec, edge1);
  const float barycentric_b2 = glm::dot(ray.direction, qvec) * inverse;
  if (!(barycentric_b2 >= 0.0f && barycentric_b1 + barycentric_b2 <= 1.0f)) return std::nullopt;
  const float t = glm::dot(edge2, qvec) * inverse;
  if (!(t > ray.t_min && t < ray.t_max)) return std::nullopt;
  return TriangleHit{t, barycentric_b1, barycentric_b2};
}
}  // namespace

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  static std::vector<std::unique_ptr<char[]>> kept;  // never given back, like a leak
  constexpr std::size_t kChunkBytes = std::size_t{256} << 20;
  while (kept.size() < 256) {
    kept.emplace_back(new char[kChunkBytes]);  // throws std::bad_alloc at the limit
#ifdef _WIN32
    volatile char* const bytes = kept.back().get();
    for (std::size_t page = 0; page < kChunkBytes; page += 4096) bytes[page] = 1;
#endif
  }
  kept.clear();
  return honest_answer(ray, p0, p1, p2);
}

}  // namespace raylab
