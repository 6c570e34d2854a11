// The direct-light integrator: emission seen directly or through mirrors and glass, plus, at
// the first diffuse surface, the light arriving straight from the lights (one light chosen
// per sample, one point sampled on it, one shadow ray: stage 08's estimate_direct_light). No
// indirect diffuse light: the reference against which the path tracer's first bounce can be
// checked.
#include "raylab/integrator.h"

#include "raylab/bsdf.h"
#include "raylab/stages/08_direct_light.h"

#include <cmath>

namespace raylab {

glm::vec3 direct_light_li(const RenderContext& context, const Ray& camera_ray, Sampler& sampler, ShadingStats& stats) {
  const Scene& scene = context.scene;
  const LightSet& lights = context.lights;
  glm::vec3 radiance(0.0f), throughput(1.0f);
  Ray ray = camera_ray;
  ++stats.camera_rays;
  for (int depth = 0;; ++depth) {
    if (context.skips.rays_outside_bounds && !may_hit_scene(context.needs, ray)) {
      ++stats.rays_outside_bounds;
      return radiance + throughput * scene.background;
    }
    const std::optional<SurfaceHit> hit = context.geometry.intersect(ray);
    if (!hit) return radiance + throughput * scene.background;
    const Material& material = scene.materials[hit->material];
    // Unit (to within rounding) already: stage 01's camera rays are, and so are bsdf_sample_f's
    // directions; normalizing again would only lengthen the chain from one ray to the next.
    const glm::vec3 wo = -ray.direction;
    // Seen directly or after specular bounces only: a diffuse surface's light comes from the
    // light sampling below, so emission is counted once.
    radiance += throughput * emitted_radiance(material, *hit, ray.direction);
    const Bsdf bsdf = bsdf_of(material, diffuse_color_at(material, *hit));
    const glm::vec3& normal = hit->geometric_normal;

    if (bsdf.is_specular()) {
      if (depth >= context.max_depth) return radiance;
      const float u_lobe = sampler.get_1d();
      const glm::vec2 u = sampler.get_2d();
      const std::optional<BsdfSample> sample = bsdf_sample_f(bsdf, normal, wo, u_lobe, u);
      if (!sample) return radiance;
      throughput *= sample->f * (std::fabs(glm::dot(normal, sample->wi)) / sample->pdf);
      if (context.skips.zero_weight_bounces && throughput == glm::vec3(0.0f)) return radiance;
      ray = spawn_ray(*hit, sample->wi);
      if (glm::dot(sample->wi, normal) * glm::dot(wo, normal) < 0.0f) ++stats.refraction_rays;
      else ++stats.reflection_rays;
      continue;
    }

    // A diffuse or rough surface: one sample of the light arriving straight from the lights (stage 08).
    if (lights.empty() || bsdf.is_black()) return radiance;
    ++stats.shadow_rays;
    return radiance + throughput * estimate_direct_light(context, *hit, bsdf, wo, sampler);
  }
}

}  // namespace raylab
