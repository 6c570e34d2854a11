// Whitted-style shading as in GAMES101 assignment 5, with pbrt-v4's robust ray offsets.
#pragma once

#include "raylab/geometry.h"
#include "raylab/scene.h"

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

struct ShadingStats {
  std::uint64_t rays = 0;  // closest-hit and shadow rays traced
};

// The colour seen along `ray`: background if nothing is hit; black past max_depth bounces.
glm::vec3 trace_whitted(const Scene& scene, const SceneGeometry& geometry, const Ray& ray,
                        int depth, int max_depth, ShadingStats& stats);

}  // namespace raylab
