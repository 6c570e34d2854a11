// Grader self-test submission (stage 08_direct_light): the shadow ray runs the whole way to the
// light's point and past it (a unit direction, t_max = infinity): an area light is scene geometry,
// so the ray hits the light itself and every estimate is black where the light is unblocked.
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
  if (f == glm::vec3(0.0f)) return glm::vec3(0.0f);
  Ray shadow;
  shadow.origin = offset_ray_origin(hit, s->direction);
  shadow.direction = s->direction;  // the mistake: t_max left at infinity
  if (context.geometry.occluded(shadow)) return glm::vec3(0.0f);
  return f * s->radiance * (std::fabs(glm::dot(hit.geometric_normal, s->direction)) / (s->pdf * probability));
}
}  // namespace raylab
