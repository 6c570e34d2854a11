// Stage 08_direct_light: radiometry, and the light arriving straight from the lights. Write the
// functions in assignments/08_direct_light/direct_light.cpp (its comments are the full
// contract); handout: docs/08_direct_light.md. The framework's BSDFs (raylab/bsdf.h) and area
// lights (raylab/lights.h) call lambertian_f and area_pdf_to_solid_angle, and the direct-light
// and path integrators call estimate_direct_light at every diffuse surface.
//
// Units: power (flux) in W, intensity in W/sr, irradiance in W/m^2, radiance in W/(m^2 sr),
// densities of directions per steradian, of points per unit area; every colour is per channel.
#pragma once

#include "raylab/bsdf.h"
#include "raylab/geometry.h"
#include "raylab/integrator.h"
#include "raylab/sampler.h"

#include <glm/glm.hpp>

namespace raylab {

// The intensity (W/sr) of a point light that sends `power` (W) equally in all directions.
glm::vec3 point_light_intensity(const glm::vec3& power);

// The irradiance (W/m^2) that a point light of `intensity` at `light_position` gives a surface
// at `point` whose unit normal is `normal` (0 when the light is behind the surface). No shadows.
glm::vec3 point_light_irradiance(const glm::vec3& intensity, const glm::vec3& light_position, const glm::vec3& point,
                                 const glm::vec3& normal);

// The BSDF value of a Lambertian (ideal diffuse) surface of `albedo` (each channel in [0, 1]),
// the same for every pair of directions on its side.
glm::vec3 lambertian_f(const glm::vec3& albedo);

// A point sampled on a light with density `pdf_area` (per unit area), seen from `distance`
// away, whose normal makes the angle with cosine `cos_at_light` (> 0) with the direction
// towards the shading point: the density of that direction per steradian.
float area_pdf_to_solid_angle(float pdf_area, float distance, float cos_at_light);

// One sample of the light arriving straight from the scene's lights (context.lights) at the
// diffuse surface point `hit` and reflected by `bsdf` towards unit `wo`: choose a light, a
// point on it, test the shadow ray, weigh by the densities. Its expected value is the direct
// lighting; random numbers from `sampler` only.
glm::vec3 estimate_direct_light(const RenderContext& context, const SurfaceHit& hit, const Bsdf& bsdf,
                                const glm::vec3& wo, Sampler& sampler);

}  // namespace raylab
