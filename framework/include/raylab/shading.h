// Whitted-style shading as in GAMES101 assignment 5, with pbrt-v4's robust ray offsets.
#pragma once

#include "raylab/geometry.h"
#include "raylab/scene.h"
#include "raylab/scene_analysis.h"

#include <cstdint>

namespace raylab {

// Mirror direction of `incident` (pointing towards the surface) about unit `normal`.
glm::vec3 reflect(const glm::vec3& incident, const glm::vec3& normal);

// Refracted direction of unit `incident` through a surface with unit `normal` (either side)
// and index of refraction `ior` (outside 1); zero vector on total internal reflection.
glm::vec3 refract(const glm::vec3& incident, const glm::vec3& normal, float ior);

// Fraction of light reflected (unpolarised Fresnel equations) for unit `incident`.
float fresnel_reflectance(const glm::vec3& incident, const glm::vec3& normal, float ior);

// A ray origin just off the surface on the side `direction` leaves towards: the hit point
// moved along the geometric normal by the bound on its error (pbrt-v4, OffsetRayOrigin), then
// rounded away from the surface. No fixed epsilon: works at any scale.
glm::vec3 offset_ray_origin(const SurfaceHit& hit, const glm::vec3& direction);

// The work done, counted (exact on any machine, unlike time).
struct ShadingStats {
  std::uint64_t camera_rays = 0;
  std::uint64_t reflection_rays = 0;
  std::uint64_t refraction_rays = 0;
  std::uint64_t shadow_rays = 0;
  std::uint64_t rays_outside_bounds = 0;  // ended by the scene's bounding sphere, untraced

  std::uint64_t rays() const { return camera_rays + reflection_rays + refraction_rays + shadow_rays; }
  ShadingStats& operator+=(const ShadingStats& other);
};

// Everything the rays of one render share.
struct Integrator {
  const Scene& scene;
  const SceneGeometry& geometry;
  SceneNeeds needs;
  int max_depth = 5;  // bounces after the camera ray
  // Leave out work that cannot change the image (scene_analysis.h; zero-weight bounces; shadow
  // rays towards lights behind the surface; any-hit instead of closest hit for shadows). Off
  // only to measure what the skips save: the image is the same either way.
  bool skip_unneeded_work = true;

  Integrator(const Scene& scene_, const SceneGeometry& geometry_, int max_depth_, bool skip_unneeded_work_);
};

// The colour seen along a camera ray: background if nothing is hit.
glm::vec3 trace_camera_ray(const Integrator& integrator, const Ray& ray, ShadingStats& stats);

}  // namespace raylab
