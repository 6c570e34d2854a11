// The scene's geometry as the renderer sees it: closest-hit and any-hit queries over all
// spheres and triangles, calling the stage functions (02_sphere, 03_triangle) for each test.
#pragma once

#include "raylab/ray.h"
#include "raylab/scene.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace raylab {

// Everything shading needs about the closest hit, filled in after t_hit is known.
struct SurfaceHit {
  float t_hit = 0.0f;
  glm::vec3 point{0.0f};
  glm::vec3 point_error{0.0f};       // a bound on |computed point - true point| per axis
  glm::vec3 geometric_normal{0.0f};  // unit length; outward for spheres, by winding for triangles
  glm::vec2 texcoord{0.0f};
  bool has_texcoord = false;
  std::uint32_t material = 0;
};

class SceneGeometry {
 public:
  explicit SceneGeometry(const Scene& scene);

  // The closest hit in (ray.t_min, ray.t_max), or nullopt.
  std::optional<SurfaceHit> intersect(const Ray& ray) const;
  // Whether anything is hit in (ray.t_min, ray.t_max): stops at the first hit found.
  bool occluded(const Ray& ray) const;

  std::size_t sphere_count() const { return spheres_.size(); }
  std::size_t triangle_count() const { return triangles_.size(); }

 private:
  struct Triangle {
    glm::vec3 p0, p1, p2;
    std::uint32_t mesh;
    std::uint32_t first_index;  // into the mesh's indices: its 3 vertices start here
  };
  enum class Kind : std::uint8_t { None, Sphere, Triangle };

  const Scene& scene_;
  std::vector<Sphere> spheres_;
  std::vector<Triangle> triangles_;
};

}  // namespace raylab
