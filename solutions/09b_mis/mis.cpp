// Reference solution, stage 09b_mis (multiple importance sampling). The contract is in
// assignments/09b_mis/mis.cpp and docs/09b_mis.md.
#include "raylab/stages/09b_mis.h"

#include "raylab/bsdf.h"
#include "raylab/lights.h"
#include "raylab/shading.h"

#include <cmath>
#include <optional>

namespace raylab {

float power_heuristic(int count_f, float pdf_f, int count_g, float pdf_g) {
  const float f = static_cast<float>(count_f) * pdf_f, g = static_cast<float>(count_g) * pdf_g;
  if (std::isinf(f)) return 1.0f;  // a delta: no other strategy can make this sample
  if (!(f > 0.0f)) return 0.0f;    // f cannot make it (also when neither can: 0, not 0 / 0)
  return (f * f) / (f * f + g * g);
}

namespace {

// One light sample at the diffuse surface point `hit` (stage 08's estimate_direct_light), weighted
// against the BSDF sampling of the same direction when a BSDF sample follows this vertex.
glm::vec3 light_sample_mis(const RenderContext& context, const SurfaceHit& hit, const Bsdf& bsdf, const glm::vec3& wo,
                           Sampler& sampler, bool bsdf_sample_follows) {
  const LightSet& lights = context.lights;
  if (lights.empty()) return glm::vec3(0.0f);
  float choice_probability = 0.0f;
  const Light& light = lights[lights.choose(sampler.get_1d(), &choice_probability)];
  const std::optional<LightSample> light_sample = sample_li(light, hit.point, sampler.get_2d());
  if (!light_sample) return glm::vec3(0.0f);
  const glm::vec3& normal = hit.geometric_normal;
  const glm::vec3 f = bsdf_f(bsdf, normal, wo, light_sample->direction);
  if (f == glm::vec3(0.0f)) return glm::vec3(0.0f);
  Ray shadow;
  shadow.origin = offset_ray_origin(hit, light_sample->direction);
  shadow.direction = light_sample->point - shadow.origin;
  shadow.t_max = 1.0f - 1e-4f;
  if (context.geometry.occluded(shadow)) return glm::vec3(0.0f);
  // The light strategy's density of this direction: choosing the light, then the point on it.
  const float pdf_light = light_sample->pdf * choice_probability;
  // Weight 1 where the BSDF cannot find this light: a point light (a delta), or the last vertex.
  float weight = 1.0f;
  if (!light_sample->is_delta && bsdf_sample_follows)
    weight = power_heuristic(1, pdf_light, 1, bsdf_pdf(bsdf, normal, wo, light_sample->direction));
  const float cos_surface = std::fabs(glm::dot(normal, light_sample->direction));
  return f * light_sample->radiance * (weight * cos_surface / pdf_light);
}

}  // namespace

glm::vec3 path_radiance_mis(const RenderContext& context, const Ray& camera_ray, Sampler& sampler) {
  const Scene& scene = context.scene;
  glm::vec3 radiance(0.0f);    // gathered so far
  glm::vec3 throughput(1.0f);  // the product of f |cos| / pdf (and 1 / p) along the path
  Ray ray = camera_ray;
  // How the ray was made: from the camera or a mirror or glass (specular: no light sample could
  // make this path, the emission found counts fully), or sampled from a diffuse BSDF with density
  // previous_bsdf_pdf at previous_point (the emission found is weighted against light sampling).
  bool previous_specular = true;
  float previous_bsdf_pdf = 0.0f;
  glm::vec3 previous_point(0.0f);
  for (int depth = 0;; ++depth) {
    const std::optional<SurfaceHit> hit = context.geometry.intersect(ray);
    if (!hit) return radiance + throughput * scene.background;
    const Material& material = scene.materials[hit->material];
    // Unit (to within rounding) already: stage 01's camera rays are, and so are bsdf_sample_f's
    // directions; normalizing again would only lengthen the chain from one ray to the next.
    const glm::vec3 wo = -ray.direction;
    const glm::vec3 emitted = emitted_radiance(material, *hit, ray.direction);
    if (emitted != glm::vec3(0.0f)) {
      float weight = 1.0f;
      if (!previous_specular)
        weight = power_heuristic(1, previous_bsdf_pdf, 1, context.lights.pdf_li(previous_point, -wo));
      radiance += throughput * emitted * weight;
    }
    const Bsdf bsdf = bsdf_of(material, diffuse_color_at(material, *hit));
    const glm::vec3& normal = hit->geometric_normal;
    const bool bsdf_sample_follows = depth < context.max_depth;
    if (!bsdf.is_specular())
      radiance += throughput * light_sample_mis(context, *hit, bsdf, wo, sampler, bsdf_sample_follows);

    if (!bsdf_sample_follows) return radiance;
    // Russian roulette, as in stage 09 (a path that goes on carries 1 / p, so the weighted
    // emission it finds keeps its expectation).
    const float p = context.continue_probability(depth, throughput);
    if (p < 1.0f) {
      if (sampler.get_1d() >= p) return radiance;
      throughput /= p;
    }
    const float u_lobe = sampler.get_1d();
    const glm::vec2 u = sampler.get_2d();
    const std::optional<BsdfSample> sample = bsdf_sample_f(bsdf, normal, wo, u_lobe, u);
    if (!sample) return radiance;
    throughput *= sample->f * (std::fabs(glm::dot(normal, sample->wi)) / sample->pdf);
    if (throughput == glm::vec3(0.0f)) return radiance;
    previous_specular = sample->is_specular;
    previous_bsdf_pdf = sample->pdf;
    previous_point = hit->point;
    ray = spawn_ray(*hit, sample->wi);
  }
}

}  // namespace raylab
