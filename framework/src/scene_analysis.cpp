#include "raylab/scene_analysis.h"

#include <algorithm>
#include <cmath>

namespace raylab {

SceneNeeds analyse_scene(const Scene& scene) {
  SceneNeeds needs;
  // A bounding box of everything, then the sphere around it, grown by a relative margin far
  // above float rounding so that no hit on its edge is lost.
  glm::dvec3 low(INFINITY), high(-INFINITY);
  for (const Sphere& sphere : scene.spheres) {
    low = glm::min(low, glm::dvec3(sphere.center) - double(sphere.radius));
    high = glm::max(high, glm::dvec3(sphere.center) + double(sphere.radius));
  }
  for (const TriangleMesh& mesh : scene.meshes)
    for (const glm::vec3& p : mesh.positions) {
      low = glm::min(low, glm::dvec3(p));
      high = glm::max(high, glm::dvec3(p));
    }
  needs.has_geometry = low.x <= high.x;
  if (needs.has_geometry) {
    needs.bounds_center = 0.5 * (low + high);
    const double half_diagonal = 0.5 * glm::length(high - low);
    const double scale = std::max({glm::length(low), glm::length(high), half_diagonal});
    needs.bounds_radius = half_diagonal * (1.0 + 1e-3) + 1e-4 * scale;
  }
  return needs;
}

bool may_hit_scene(const SceneNeeds& needs, const Ray& ray) {
  if (!needs.has_geometry) return false;
  const glm::dvec3 origin_to_center = needs.bounds_center - glm::dvec3(ray.origin);
  const glm::dvec3 direction(ray.direction);
  const double radius_squared = needs.bounds_radius * needs.bounds_radius;
  const double distance_squared = glm::dot(origin_to_center, origin_to_center);
  if (distance_squared <= radius_squared) return true;  // starts inside
  const double along = glm::dot(origin_to_center, direction);
  if (along <= 0.0) return false;  // the sphere is behind the origin
  const double line_distance_squared = distance_squared - along * along / glm::dot(direction, direction);
  return line_distance_squared <= radius_squared;
}

}  // namespace raylab
