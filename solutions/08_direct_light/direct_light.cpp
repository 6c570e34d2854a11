// Reference solution, stage 08_direct_light (radiometry and direct light). The contract is in
// assignments/08_direct_light/direct_light.cpp and docs/08_direct_light.md.
#include "raylab/stages/08_direct_light.h"

#include "raylab/lights.h"
#include "raylab/math.h"
#include "raylab/shading.h"

#include <cmath>
#include <optional>

namespace raylab {

glm::vec3 point_light_intensity(const glm::vec3& power) {
  // The power leaves through the whole sphere of directions, 4 pi steradians.
  return power / (4.0f * kPi);
}

glm::vec3 point_light_irradiance(const glm::vec3& intensity, const glm::vec3& light_position, const glm::vec3& point,
                                 const glm::vec3& normal) {
  const glm::vec3 to_light = light_position - point;
  const float distance_squared = glm::dot(to_light, to_light);
  if (!(distance_squared > 0.0f)) return glm::vec3(0.0f);
  const float cos_surface = glm::dot(normal, to_light) / std::sqrt(distance_squared);
  if (!(cos_surface > 0.0f)) return glm::vec3(0.0f);  // the light is behind the surface
  return intensity * (cos_surface / distance_squared);
}

glm::vec3 lambertian_f(const glm::vec3& albedo) { return albedo * (1.0f / kPi); }

float area_pdf_to_solid_angle(float pdf_area, float distance, float cos_at_light) {
  // A small patch dA at the light covers the solid angle dA cos / distance^2.
  return pdf_area * (distance * distance) / cos_at_light;
}

glm::vec3 estimate_direct_light(const RenderContext& context, const SurfaceHit& hit, const Bsdf& bsdf,
                                const glm::vec3& wo, Sampler& sampler) {
  const LightSet& lights = context.lights;
  if (lights.empty()) return glm::vec3(0.0f);
  // One light, chosen uniformly, then one point (or, for a point light, the one direction) on it.
  float choice_probability = 0.0f;
  const Light& light = lights[lights.choose(sampler.get_1d(), &choice_probability)];
  const std::optional<LightSample> light_sample = sample_li(light, hit.point, sampler.get_2d());
  if (!light_sample) return glm::vec3(0.0f);
  const glm::vec3& normal = hit.geometric_normal;
  const glm::vec3 f = bsdf_f(bsdf, normal, wo, light_sample->direction);
  if (f == glm::vec3(0.0f)) return glm::vec3(0.0f);  // the light is behind the surface
  // The shadow ray: from just off the surface to just short of the light's point.
  Ray shadow;
  shadow.origin = offset_ray_origin(hit, light_sample->direction);
  shadow.direction = light_sample->point - shadow.origin;
  shadow.t_max = 1.0f - 1e-4f;
  if (context.geometry.occluded(shadow)) return glm::vec3(0.0f);
  const float cos_surface = std::fabs(glm::dot(normal, light_sample->direction));
  return f * light_sample->radiance * (cos_surface / (light_sample->pdf * choice_probability));
}

}  // namespace raylab
