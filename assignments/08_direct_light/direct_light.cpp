// Stage 08_direct_light: radiometry, and the light arriving straight from the lights.
//                                                               Handout: docs/08_direct_light.md
//
// Light is measured in a few quantities (handout section 1): power or flux (W), intensity
// (W/sr: power per solid angle), irradiance (W/m^2: power arriving per area) and radiance
// (W/(m^2 sr): what a camera pixel measures). A BSDF f turns irradiance arriving from one
// direction into radiance leaving towards another.
//
// CONVENTIONS
//   Colours are glm::vec3, one value per channel (red, green, blue); compute the same formula
//   for each channel (glm does it for you: vec3 * float, vec3 / float, vec3 * vec3).
//   Directions wo and wi point AWAY from the surface (wo towards the viewer, wi towards the
//   light). Normals are unit length. Densities (pdfs) of points are per unit area, of
//   directions per steradian.
//   The framework calls lambertian_f (every diffuse BSDF, raylab/bsdf.h) and
//   area_pdf_to_solid_angle (every area light, raylab/lights.h): write them first.
//
// READ docs/08_direct_light.md: section 1 (flux, intensity, irradiance, radiance, with worked
//   numbers), section 2 (point lights), section 3 (the Lambertian BSDF), section 4 (area
//   lights and densities), section 5 (the one-sample estimator), section 6 (common mistakes,
//   which the autograder's hints name, and how to check).
//
// HOW TO CHECK
//   build/bin/autograder --stage 08_direct_light
//   build/bin/raylab render scenes/cornell_direct.json -o direct.png --integrator direct --spp 64
#include "raylab/error.h"
#include "raylab/lights.h"
#include "raylab/shading.h"
#include "raylab/stages/08_direct_light.h"

namespace raylab {

// A point light sends `power` (W) equally in every direction. RETURN its intensity (W/sr).
glm::vec3 point_light_intensity(const glm::vec3& power) {
  (void)power;
  // Delete the line below when you write the function (handout section 2).
  throw NotImplemented("point_light_intensity");
}

// RETURN the irradiance (W/m^2) at `point`, on a surface of unit `normal`, from a point light
// of `intensity` (W/sr) at `light_position`: it falls off with the squared distance and with
// the cosine between the normal and the direction to the light. 0 when the light is behind the
// surface (that cosine <= 0). No shadows here: the function sees no scene.
glm::vec3 point_light_irradiance(const glm::vec3& intensity, const glm::vec3& light_position, const glm::vec3& point,
                                 const glm::vec3& normal) {
  (void)intensity;
  (void)light_position;
  (void)point;
  (void)normal;
  throw NotImplemented("point_light_irradiance");
}

// RETURN the BSDF value f of a Lambertian surface of `albedo` (the fraction of the light it
// reflects, per channel). It is the same for every pair of directions, and chosen so that the
// surface reflects exactly `albedo` of the light it receives (handout section 3).
glm::vec3 lambertian_f(const glm::vec3& albedo) {
  (void)albedo;
  throw NotImplemented("lambertian_f");
}

// A point was sampled on an area light with density `pdf_area` (per unit area). It is
// `distance` away from the shading point, and the light's normal there makes an angle with
// cosine `cos_at_light` (> 0) with the direction back to the shading point. RETURN the density
// of the direction towards it per steradian (handout section 4).
float area_pdf_to_solid_angle(float pdf_area, float distance, float cos_at_light) {
  (void)pdf_area;
  (void)distance;
  (void)cos_at_light;
  throw NotImplemented("area_pdf_to_solid_angle");
}

// One sample of the light arriving straight from the lights at the diffuse surface point `hit`
// (hit.point, hit.geometric_normal) and reflected by `bsdf` towards `wo`. Its average over many
// calls must be the direct lighting (handout section 5). The tools you need:
//   context.lights            every light (raylab/lights.h); empty(): no light, RETURN black
//   context.lights.choose(u, &probability)   a light's index for u in [0, 1), and the
//                             probability it had of being chosen
//   sample_li(light, hit.point, uv)   a point on that light (uv in [0, 1)^2): its direction,
//                             distance, point, radiance and density (pdf, per steradian); or
//                             nullopt when it cannot contribute
//   bsdf_f(bsdf, hit.geometric_normal, wo, wi)   the BSDF value (0 when wi is behind)
//   offset_ray_origin(hit, direction) and context.geometry.occluded(ray)   the shadow ray
//                             (raylab/shading.h, raylab/geometry.h)
//   sampler.get_1d(), sampler.get_2d()   your random numbers, the only ones (no rand(): the
//                             same seed must give the same estimates)
// RETURN f * radiance * |cos(theta at the surface)| / (pdf * probability), or black when the
// shadow ray is blocked. The shadow ray starts at offset_ray_origin(hit, direction), points at
// the light's point itself (direction = point - origin, so t = 1 is that point) and stops just
// short of it, t_max = 1 - 1e-4: an area light is scene geometry, so a ray that reaches its point
// (or t_max = infinity) hits the light itself and every estimate is black (handout section 5).
glm::vec3 estimate_direct_light(const RenderContext& context, const SurfaceHit& hit, const Bsdf& bsdf,
                                const glm::vec3& wo, Sampler& sampler) {
  (void)context;
  (void)hit;
  (void)bsdf;
  (void)wo;
  (void)sampler;
  // Delete the line below when you write the function (handout section 5).
  throw NotImplemented("estimate_direct_light");
}

}  // namespace raylab
