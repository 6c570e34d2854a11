// Grader self-test submission (stage 08_direct_light): no shadow ray: light passes through
// everything between the surface and the light.
#define estimate_direct_light reference_estimate_direct_light
#include "../../solutions/08_direct_light/direct_light.cpp"
#undef estimate_direct_light

namespace raylab {
glm::vec3 estimate_direct_light(const RenderContext& context, const SurfaceHit& hit, const Bsdf& bsdf,
                                const glm::vec3& wo, Sampler& sampler) {
  if (context.lights.empty()) return glm::vec3(0.0f);
  float probability = 0.0f;
  const Light& light = context.lights[context.lights.choose(sampler.get_1d(), &probability)];
  const std::optional<LightSample> s = sample_li(light, hit.point, sampler.get_2d());
  if (!s) return glm::vec3(0.0f);
  const glm::vec3 f = bsdf_f(bsdf, hit.geometric_normal, wo, s->direction);
  return f * s->radiance * (std::fabs(glm::dot(hit.geometric_normal, s->direction)) / (s->pdf * probability));
}
}  // namespace raylab
