// SceneGeometry, part 4 of 4: the public queries, and the hit details. The closest t comes
// from the trees (geometry_bvh_adapters.cpp) or from testing every object
// (geometry_brute_force.cpp); only then is the hit record turned into what shading needs: the
// point and its error bound, the geometric normal, texture coordinates and material.
// (geometry_build.cpp builds the trees.)
#include "geometry_query.h"

#include "raylab/trace_recorder.h"

#include <cmath>

namespace raylab {

SceneGeometry::Triangle::Triangle(const glm::vec3& p0_, const glm::vec3& p1_, const glm::vec3& p2_,
                                  std::uint32_t mesh_, std::uint32_t first_index_)
    : p0(p0_), p1(p1_), p2(p2_), mesh(mesh_), first_index(first_index_) {
  const glm::vec3 unnormalised = glm::cross(p1 - p0, p2 - p0);
  const float length = glm::length(unnormalised);
  has_area = length > 0.0f;
  normal = has_area ? unnormalised / length : glm::vec3(0.0f);
}

SceneGeometry::Work SceneGeometry::take_thread_work() {
  const Work work = thread_tree_work;
  thread_tree_work = Work();
  return work;
}

RAYLAB_RECORDED_VERSION std::optional<SurfaceHit> SceneGeometry::intersect_recorded(const Ray& ray) const {
  PausedRecording paused;
  return record_intersect(*paused.recorder, ray, intersect(ray));
}

RAYLAB_RECORDED_VERSION bool SceneGeometry::occluded_recorded(const Ray& ray) const {
  PausedRecording paused;
  return record_occluded(*paused.recorder, ray, occluded(ray));
}

std::optional<SurfaceHit> SceneGeometry::intersect(const Ray& ray) const {
  // Every return hands back `result`, so that the hit is written where the caller reads it
  // (one named return value) and not copied: a copy reads back in 16-byte pieces what was
  // just written in 4- and 8-byte ones, which the processor cannot forward from its stores,
  // and the next ray waits for it (docs/performance.md, "Stores read back whole").
  std::optional<SurfaceHit> result;
  if (RAYLAB_UNLIKELY(active_trace_recorder)) {  // returned as `result` too: see above
    result = intersect_recorded(ray);
    return result;
  }
  if (only_tree_) {
    std::uint32_t triangle = 0;
    TriangleHit details;
    if (only_tree_->closest_hit(ray, triangle, details) && triangle < triangles_.size())
      fill_triangle_surface_hit(result.emplace(), triangle, details, ray);
    return result;
  }
  // Find the closest t first (shrinking t_max after every hit), then fill the record once.
  HitRecord record;
  Query query{this, &record, /*any_hit=*/false};
  const std::optional<float> t_hit = intersect_objects(ray, query);
  if (!t_hit || record.kind == Kind::None) return result;
  if (record.kind == Kind::Triangle) {
    TriangleHit details = record.triangle_hit;
    details.t_hit = *t_hit;
    fill_triangle_surface_hit(result.emplace(), record.index, details, ray);
    return result;
  }
  SurfaceHit& hit = result.emplace();
  hit.t_hit = *t_hit;
  const Sphere& sphere = spheres_[record.index];
  // Re-project the hit point onto the surface: its error is then a few ulps (pbrt-v4 6.8.5).
  const glm::vec3 outward = glm::normalize(ray.at(hit.t_hit) - sphere.center);
  hit.point = sphere.center + sphere.radius * outward;
  hit.point_error = gamma_bound(5) * glm::abs(hit.point) + gamma_bound(5) * glm::abs(sphere.center);
  hit.geometric_normal = sphere.faces_inward ? -outward : outward;
  hit.material = sphere.material;
  return result;
}

void SceneGeometry::fill_triangle_surface_hit(SurfaceHit& hit, std::uint32_t triangle, const TriangleHit& details,
                                              const Ray& ray) const {
  const Triangle& tri = triangles_[triangle];
  const TriangleMesh& mesh = scene_.meshes[tri.mesh];
  const float b1 = details.barycentric_b1, b2 = details.barycentric_b2;
  const float b0 = 1.0f - b1 - b2;
  hit.t_hit = details.t_hit;
  // The point from barycentrics is far more accurate than origin + t * direction.
  hit.point = b0 * tri.p0 + b1 * tri.p1 + b2 * tri.p2;
  hit.point_error = gamma_bound(7) * (glm::abs(b0 * tri.p0) + glm::abs(b1 * tri.p1) + glm::abs(b2 * tri.p2));
  // A degenerate triangle has no normal; face the ray so that shading stays finite.
  hit.geometric_normal = tri.has_area ? tri.normal : -glm::normalize(ray.direction);
  if (!mesh.texcoords.empty()) {
    hit.texcoord = b0 * mesh.texcoords[mesh.indices[tri.first_index]] +
                   b1 * mesh.texcoords[mesh.indices[tri.first_index + 1]] +
                   b2 * mesh.texcoords[mesh.indices[tri.first_index + 2]];
    hit.has_texcoord = true;
  }
  hit.material = mesh.material;
}

bool SceneGeometry::occluded(const Ray& ray) const {
  if (RAYLAB_UNLIKELY(active_trace_recorder)) return occluded_recorded(ray);
  if (only_tree_) return only_tree_->any_hit(ray).has_value();
  HitRecord record;
  Query query{this, &record, /*any_hit=*/true};
  return intersect_objects(ray, query).has_value();
}

}  // namespace raylab
