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
  // The rays that reached the geometry: all but those the bounding sphere ended.
  std::uint64_t traced_rays() const { return rays() - rays_outside_bounds; }
  ShadingStats& operator+=(const ShadingStats& other);
};

// The work the renderer leaves out because it cannot change the image. Each can be turned off
// to measure what it saves (bench/render_bench.cpp); the image is the same either way.
struct Skips {
  bool rays_outside_bounds = true;      // rays that miss the scene's bounding sphere end at once
  bool zero_weight_bounces = true;      // no reflection or refraction ray whose weight is 0
  bool needless_shadow_rays = true;     // none towards a light behind the surface, or from a black one
  bool any_hit_shadow_rays = true;      // a shadow ray ends at its first hit, not its closest
  bool no_bvh_for_small_sets = true;    // a handful of primitives is tested one by one

  static Skips none() { return Skips{false, false, false, false, false}; }
};

// Everything the rays of one render share.
struct Integrator {
  const Scene& scene;
  const SceneGeometry& geometry;
  SceneNeeds needs;
  int max_depth = 5;  // bounces after the camera ray
  Skips skips;

  Integrator(const Scene& scene_, const SceneGeometry& geometry_, int max_depth_, const Skips& skips_);
};

// The colour seen along a camera ray: background if nothing is hit.
glm::vec3 trace_camera_ray(const Integrator& integrator, const Ray& ray, ShadingStats& stats);

}  // namespace raylab
