// What every integrator shares: reflection and refraction directions, Fresnel, robust
// secondary-ray origins (pbrt-v4), the work counters and the skips.
#pragma once

#include "raylab/geometry.h"
#include "raylab/scene.h"

#include <cmath>
#include <cstdint>

namespace raylab {

// Mirror direction of `incident` (pointing towards the surface) about unit `normal`.
inline glm::vec3 reflect(const glm::vec3& incident, const glm::vec3& normal) {
  return incident - 2.0f * glm::dot(incident, normal) * normal;
}

// Refracted direction of unit `incident` through a surface with unit `normal` (either side)
// and index of refraction `ior` (outside 1); zero vector on total internal reflection.
glm::vec3 refract(const glm::vec3& incident, const glm::vec3& normal, float ior);

// Fraction of light reflected (unpolarised Fresnel equations) for unit `incident`.
float fresnel_reflectance(const glm::vec3& incident, const glm::vec3& normal, float ior);

// A ray origin just off the surface on the side `direction` leaves towards: the hit point
// moved along the geometric normal by the bound on its error (pbrt-v4, OffsetRayOrigin), then
// rounded away from the surface. No fixed epsilon: works at any scale.
glm::vec3 offset_ray_origin(const SurfaceHit& hit, const glm::vec3& direction);

// A ray leaving the surface of `hit` along `direction` (not necessarily unit length), from
// offset_ray_origin, with t_min = 0 and t_max = infinity.
inline Ray spawn_ray(const SurfaceHit& hit, const glm::vec3& direction) {
  Ray ray;
  ray.origin = offset_ray_origin(hit, direction);
  ray.direction = direction;
  return ray;
}

// The radiance an emitting surface sends back along a ray of direction `ray_direction` that
// hit it: its emission on its front side (where the geometric normal points), 0 elsewhere.
inline glm::vec3 emitted_radiance(const Material& material, const SurfaceHit& hit, const glm::vec3& ray_direction) {
  return glm::dot(ray_direction, hit.geometric_normal) < 0.0f ? material.emission : glm::vec3(0.0f);
}

// The material's diffuse colour at the hit: its checkerboard where the hit has texture
// coordinates, its diffuse_color otherwise.
inline glm::vec3 diffuse_color_at(const Material& material, const SurfaceHit& hit) {
  if (!material.checkerboard || !hit.has_texcoord) return material.diffuse_color;
  const Checkerboard& board = *material.checkerboard;
  auto fraction = [](float x) { return x - std::floor(x); };  // in [0, 1), also below zero
  const bool s_half = fraction(hit.texcoord.x * board.scale) > 0.5f;
  const bool t_half = fraction(hit.texcoord.y * board.scale) > 0.5f;
  return (s_half != t_half) ? board.color_b : board.color_a;
}

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

}  // namespace raylab
