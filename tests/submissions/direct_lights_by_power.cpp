// Grader self-test submission (stage 08_direct_light), correct: the light chosen with probability
// proportional to its power (light_power) instead of uniformly, and divided by that probability.
// Expected: full marks.
#define estimate_direct_light reference_estimate_direct_light
#include "../../solutions/08_direct_light/direct_light.cpp"
#undef estimate_direct_light

namespace raylab {
glm::vec3 estimate_direct_light(const RenderContext& context, const SurfaceHit& hit, const Bsdf& bsdf,
                                const glm::vec3& wo, Sampler& sampler) {
  const std::vector<Light>& lights = context.lights.lights();
  if (lights.empty()) return glm::vec3(0.0f);
  auto power_of = [](const Light& light) {
    const glm::vec3 power = light_power(light);
    return power.x + power.y + power.z;
  };
  float total = 0.0f;
  for (const Light& light : lights) total += power_of(light);
  if (!(total > 0.0f)) return glm::vec3(0.0f);
  const float u = sampler.get_1d() * total;
  std::size_t chosen = lights.size() - 1;
  float running = 0.0f;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    running += power_of(lights[i]);
    if (u < running) {
      chosen = i;
      break;
    }
  }
  const float probability = power_of(lights[chosen]) / total;
  const std::optional<LightSample> s = sample_li(lights[chosen], hit.point, sampler.get_2d());
  if (!s) return glm::vec3(0.0f);
  const glm::vec3 f = bsdf_f(bsdf, hit.geometric_normal, wo, s->direction);
  if (f == glm::vec3(0.0f)) return glm::vec3(0.0f);
  Ray shadow;
  shadow.origin = offset_ray_origin(hit, s->direction);
  shadow.direction = s->point - shadow.origin;
  shadow.t_max = 1.0f - 1e-4f;
  if (context.geometry.occluded(shadow)) return glm::vec3(0.0f);
  return f * s->radiance * (std::fabs(glm::dot(hit.geometric_normal, s->direction)) / (s->pdf * probability));
}
}  // namespace raylab
