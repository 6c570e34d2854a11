// Reference solution, stage 03_triangle (Moller-Trumbore). The contract is in
// assignments/03_triangle/triangle.cpp and docs/03_triangle.md.
#include "raylab/stages/03_triangle.h"

#include "moller_trumbore.h"

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0,
                                                  const glm::vec3& p1, const glm::vec3& p2) {
  // The test itself is inline in moller_trumbore.h, shared with the reference traversal.
  TriangleHit hit;
  if (!reference::moller_trumbore(ray, p0, p1 - p0, p2 - p0, hit)) return std::nullopt;
  return hit;
}

}  // namespace raylab
