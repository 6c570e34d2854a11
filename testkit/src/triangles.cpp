#include "raylab/testkit/triangles.h"

namespace raylab::testkit {

std::optional<float> test_indexed_triangle(void* triangles, const Ray& ray, std::uint32_t triangle) {
  const IndexedTriangles& mesh = *static_cast<const IndexedTriangles*>(triangles);
  const std::vector<glm::vec3>& positions = *mesh.positions;
  const std::uint32_t* corner = mesh.indices->data() + 3 * std::size_t(triangle);
  const std::optional<TriangleHit> hit = mesh.function(ray, positions[corner[0]], positions[corner[1]], positions[corner[2]]);
  if (!hit) return std::nullopt;
  return hit->t_hit;
}

}  // namespace raylab::testkit
