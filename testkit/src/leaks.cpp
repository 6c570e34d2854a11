#include "raylab/testkit/leaks.h"

#include "raylab/testkit/random_values.h"

#include <algorithm>

namespace raylab::testkit {

ClosedMesh closed_mesh(TriangleMesh generated, const glm::vec3& inside, float inside_radius) {
  ClosedMesh mesh;
  mesh.name = std::move(generated.name);
  mesh.positions = std::move(generated.positions);
  mesh.indices = std::move(generated.indices);
  mesh.inside = inside;
  mesh.inside_radius = inside_radius;
  return mesh;
}

ClosedMesh closed_icosphere(int levels, float radius, const glm::vec3& center) {
  return closed_mesh(make_icosphere(levels, radius, center), center, 0.5f * radius);
}

ClosedMesh closed_grid_cube(int n, float half_size, const glm::vec3& center) {
  return closed_mesh(make_grid_cube(n, half_size, center), center, 0.5f * half_size);
}

HitsAnyTriangle hits_any_triangle_by(const ClosedMesh& mesh, TriangleFunction function) {
  return [&mesh, function](const std::vector<Ray>& rays, const std::vector<std::vector<std::uint32_t>>& candidates) {
    auto hits = [&](const Ray& ray, std::uint32_t t) {
      const std::uint32_t* corner = mesh.indices.data() + 3 * std::size_t(t);
      return function(ray, mesh.positions[corner[0]], mesh.positions[corner[1]], mesh.positions[corner[2]]).has_value();
    };
    std::vector<bool> any(rays.size(), false);
    for (std::size_t r = 0; r < rays.size(); ++r) {
      if (candidates.empty()) {
        for (std::uint32_t t = 0; !any[r] && t < mesh.triangle_count(); ++t) any[r] = hits(rays[r], t);
      } else {
        for (std::size_t i = 0; !any[r] && i < candidates[r].size(); ++i) any[r] = hits(rays[r], candidates[r][i]);
      }
    }
    return any;
  };
}

LeakCount count_leaks(const ClosedMesh& mesh, std::uint64_t rays, Pcg32& random, const HitsAnyTriangle& hits) {
  // Which triangles touch each vertex (the candidates for a ray aimed at it or at its edges).
  std::vector<std::vector<std::uint32_t>> around_vertex(mesh.positions.size());
  const auto triangle_count = static_cast<std::uint32_t>(mesh.triangle_count());
  for (std::uint32_t t = 0; t < triangle_count; ++t)
    for (int k = 0; k < 3; ++k) around_vertex[mesh.indices[3 * std::size_t(t) + k]].push_back(t);

  constexpr std::uint64_t kBatch = 50000;  // rays per call of `hits`: bounded memory, few calls
  LeakCount count;
  std::vector<Ray> batch;
  std::vector<std::vector<std::uint32_t>> near;  // per ray: the triangles around its edge's vertices
  for (std::uint64_t first = 0; first < rays; first += kBatch) {
    batch.clear();
    near.clear();
    for (std::uint64_t r = first; r < std::min(rays, first + kBatch); ++r) {
      const std::uint32_t triangle = random.next_bounded(triangle_count);
      const int k = random_integer(random, 0, 2);
      const std::uint32_t a = mesh.indices[3 * std::size_t(triangle) + k];
      const std::uint32_t b = mesh.indices[3 * std::size_t(triangle) + (k + 1) % 3];
      glm::vec3 target = mesh.positions[a];
      if (r % 2 == 0) target = glm::mix(mesh.positions[a], mesh.positions[b], random.uniform(0.0f, 1.0f));
      Ray ray;
      ray.origin = mesh.inside + random.uniform(0.0f, 0.9f) * mesh.inside_radius * random_unit_vector(random);
      ray.direction = target - ray.origin;
      batch.push_back(ray);
      near.push_back(around_vertex[a]);
      near.back().insert(near.back().end(), around_vertex[b].begin(), around_vertex[b].end());
    }
    count.rays += batch.size();
    const std::vector<bool> near_hit = hits(batch, near);
    std::vector<Ray> missed;
    for (std::size_t r = 0; r < batch.size(); ++r)
      if (!near_hit[r]) missed.push_back(batch[r]);
    if (missed.empty()) continue;
    const std::vector<bool> any_hit = hits(missed, {});
    for (std::size_t m = 0; m < missed.size(); ++m) {
      if (any_hit[m]) continue;
      ++count.leaks;
      if (!count.first_leak) count.first_leak = missed[m];
    }
  }
  return count;
}

}  // namespace raylab::testkit
