#include "raylab/geometry.h"

#include "raylab/stages/02_sphere.h"
#include "raylab/stages/03_triangle.h"

namespace raylab {

SceneGeometry::SceneGeometry(const Scene& scene) : scene_(scene), spheres_(scene.spheres) {
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    for (std::uint32_t i = 0; i + 2 < mesh.indices.size(); i += 3)
      triangles_.push_back({mesh.positions[mesh.indices[i]], mesh.positions[mesh.indices[i + 1]],
                            mesh.positions[mesh.indices[i + 2]], m, i});
  }
}

std::optional<SurfaceHit> SceneGeometry::intersect(const Ray& ray) const {
  // Find the closest t first (shrinking t_max after every hit), then fill the record once.
  Ray search = ray;
  Kind kind = Kind::None;
  std::size_t index = 0;
  TriangleHit triangle_hit;
  for (std::size_t i = 0; i < spheres_.size(); ++i) {
    if (const auto t = intersect_ray_sphere(search, spheres_[i].center, spheres_[i].radius)) {
      search.t_max = *t;
      kind = Kind::Sphere;
      index = i;
    }
  }
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const Triangle& tri = triangles_[i];
    if (const auto hit = intersect_ray_triangle(search, tri.p0, tri.p1, tri.p2)) {
      search.t_max = hit->t_hit;
      kind = Kind::Triangle;
      index = i;
      triangle_hit = *hit;
    }
  }
  if (kind == Kind::None) return std::nullopt;

  SurfaceHit hit;
  hit.t_hit = search.t_max;
  if (kind == Kind::Sphere) {
    const Sphere& sphere = spheres_[index];
    // Re-project the hit point onto the surface: its error is then a few ulps (pbrt-v4 6.8.5).
    const glm::vec3 outward = glm::normalize(ray.at(hit.t_hit) - sphere.center);
    hit.point = sphere.center + sphere.radius * outward;
    hit.point_error = gamma_bound(5) * glm::abs(hit.point) + gamma_bound(5) * glm::abs(sphere.center);
    hit.geometric_normal = outward;
    hit.material = sphere.material;
  } else {
    const Triangle& tri = triangles_[index];
    const TriangleMesh& mesh = scene_.meshes[tri.mesh];
    const float b1 = triangle_hit.barycentric_b1, b2 = triangle_hit.barycentric_b2;
    const float b0 = 1.0f - b1 - b2;
    // The point from barycentrics is far more accurate than origin + t * direction.
    hit.point = b0 * tri.p0 + b1 * tri.p1 + b2 * tri.p2;
    hit.point_error = gamma_bound(7) * (glm::abs(b0 * tri.p0) + glm::abs(b1 * tri.p1) + glm::abs(b2 * tri.p2));
    const glm::vec3 normal = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    const float length = glm::length(normal);
    // A degenerate triangle has no normal; face the ray so that shading stays finite.
    hit.geometric_normal = length > 0.0f ? normal / length : -glm::normalize(ray.direction);
    if (!mesh.texcoords.empty()) {
      hit.texcoord = b0 * mesh.texcoords[mesh.indices[tri.first_index]] +
                     b1 * mesh.texcoords[mesh.indices[tri.first_index + 1]] +
                     b2 * mesh.texcoords[mesh.indices[tri.first_index + 2]];
      hit.has_texcoord = true;
    }
    hit.material = mesh.material;
  }
  return hit;
}

bool SceneGeometry::occluded(const Ray& ray) const {
  for (const Sphere& sphere : spheres_)
    if (intersect_ray_sphere(ray, sphere.center, sphere.radius)) return true;
  for (const Triangle& tri : triangles_)
    if (intersect_ray_triangle(ray, tri.p0, tri.p1, tri.p2)) return true;
  return false;
}

}  // namespace raylab
