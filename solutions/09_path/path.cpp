// Reference solution, stage 09_path (Monte Carlo path tracing). The contract is in
// assignments/09_path/path.cpp and docs/09_path.md.
#include "raylab/stages/09_path.h"

#include "raylab/bsdf.h"
#include "raylab/shading.h"
#include "raylab/stages/08_direct_light.h"

#include <cmath>
#include <optional>

namespace raylab {

glm::vec3 path_radiance(const RenderContext& context, const Ray& camera_ray, Sampler& sampler) {
  const Scene& scene = context.scene;
  glm::vec3 radiance(0.0f);    // gathered so far
  glm::vec3 throughput(1.0f);  // the product of f |cos| / pdf (and 1 / p) along the path
  Ray ray = camera_ray;
  // Emission is counted where the path sees it directly: from the camera or after a mirror or
  // glass. After a diffuse bounce it is not: estimate_direct_light counted it already.
  bool count_emission = true;
  for (int depth = 0;; ++depth) {
    const std::optional<SurfaceHit> hit = context.geometry.intersect(ray);
    if (!hit) return radiance + throughput * scene.background;
    const Material& material = scene.materials[hit->material];
    // Unit (to within rounding) already: stage 01's camera rays are, and so are bsdf_sample_f's
    // directions; normalizing again would only lengthen the chain from one ray to the next.
    const glm::vec3 wo = -ray.direction;
    if (count_emission) radiance += throughput * emitted_radiance(material, *hit, ray.direction);
    const Bsdf bsdf = bsdf_of(material, diffuse_color_at(material, *hit));
    const glm::vec3& normal = hit->geometric_normal;
    if (!bsdf.is_specular()) radiance += throughput * estimate_direct_light(context, *hit, bsdf, wo, sampler);

    if (depth >= context.max_depth) return radiance;
    // Russian roulette: go on with probability p, and divide by p so the expectation stays.
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
    count_emission = sample->is_specular;
    // ray = spawn_ray(*hit, sample->wi), written out: assigning a whole Ray makes GCC copy it in
    // 16-byte pieces that the processor cannot forward from the 4- and 8-byte stores that made it,
    // and the next traversal waits for them (docs/performance.md, "Stores read back whole").
    ray.origin = offset_ray_origin(*hit, sample->wi);
    ray.direction = sample->wi;
    ray.t_min = 0.0f;
    ray.t_max = kInfinity;
  }
}

}  // namespace raylab
