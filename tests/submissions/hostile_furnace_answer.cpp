// Hostile (stage 09_path): traces no path. It looks up the albedo of the surface the camera sees
// and returns the furnace's exact answer for it, 1 + a + ... + a^(max_depth + 1), with no noise.
// The furnaces' t-tests and spread tests pass; the furnaces with roulette fail their test of short
// paths (a correct path tracer's roulette ends some paths early with little light), and the
// Cornell boxes fail. The furnace without roulette passes: there a correct path tracer with
// cosine-weighted bounces is nearly noiseless too, so its output cannot tell it from this.
#include "raylab/bsdf.h"
#include "raylab/shading.h"
#include "raylab/stages/09_path.h"

namespace raylab {

glm::vec3 path_radiance(const RenderContext& context, const Ray& camera_ray, Sampler& sampler) {
  (void)sampler;
  const std::optional<SurfaceHit> hit = context.geometry.intersect(camera_ray);
  if (!hit) return context.scene.background;
  const Material& material = context.scene.materials[hit->material];
  const glm::vec3 albedo = diffuse_color_at(material, *hit);
  glm::vec3 answer(0.0f), term(1.0f);
  for (int k = 0; k <= context.max_depth + 1; ++k, term *= albedo) answer += term;
  return answer;
}

}  // namespace raylab
