// Grader self-test submissions of stage 09b_mis share this MIS path tracer: each one sets the flags
// of one common mistake (or of a correct variant) and defines power_heuristic and
// path_radiance_mis with it, so that a submission file says only what it changes.
#pragma once

#include "direct_variant.h"

#include "raylab/bsdf.h"
#include "raylab/lights.h"
#include "raylab/shading.h"
#include "raylab/stages/08_direct_light.h"
#include "raylab/stages/09b_mis.h"

#include <cmath>
#include <optional>

namespace raylab::submission {

struct MisVariant {
  // Mistakes.
  bool balance = false;                 // power_heuristic computes the balance heuristic
  bool area_pdf_in_bsdf_weight = false;  // the BSDF sample's weight takes the light's density per area
  bool delta_weighted = false;          // a point light's sample weighted like an area light's
  bool emission_unweighted = false;     // the BSDF sample's emission after a diffuse bounce: weight 1
  bool last_vertex_weighted = false;    // the light sample at depth == max_depth weighted
  bool camera_hit_weighted = false;     // previous_specular starts false: the emission the camera sees is weighted
                                        // with a BSDF density of 0 (so it counts 0)
  bool specular_hit_weighted = false;   // the emission found after a mirror or glass bounce weighted like a diffuse one's
  bool half_weights = false;            // both samples weighted 1/2: unbiased, but not the power heuristic
  bool textbook_heuristic = false;      // power_heuristic: pdf_f^2 / (pdf_f^2 + pdf_g^2), counts ignored, no guard
  bool counts_outside_square = false;   // power_heuristic: n_f pdf_f^2 / (...), no guard for an infinite pdf
  bool other_weight = false;            // power_heuristic: (n_g pdf_g)^2 / (...), the other strategy's weight
  // Correct variants.
  bool ratio_form = false;              // power_heuristic as 1 / (1 + (g / f)^2); light densities summed here
};

inline float heuristic(const MisVariant& v, float f, float g) {
  if (std::isinf(f)) return 1.0f;
  if (!(f > 0.0f)) return 0.0f;
  if (v.balance) return f / (f + g);
  if (v.half_weights) return 0.5f;
  if (v.ratio_form) {
    const float r = g / f;
    return 1.0f / (1.0f + r * r);
  }
  return f * f / (f * f + g * g);
}

// The light strategy's density of `wi` from x, per steradian (or, for the mistake, per unit area:
// GAMES101's 1 / area of the light that wi hits, times the choice probability).
inline float light_density(const RenderContext& context, const MisVariant& v, const glm::vec3& x, const glm::vec3& wi) {
  const std::vector<Light>& lights = context.lights.lights();
  if (lights.empty()) return 0.0f;
  const float choice = 1.0f / static_cast<float>(lights.size());
  if (v.area_pdf_in_bsdf_weight) {
    for (const Light& light : lights)
      if (pdf_li(light, x, wi) > 0.0f) return choice / light.area;
    return 0.0f;
  }
  if (!v.ratio_form) return context.lights.pdf_li(x, wi);
  float sum = 0.0f;
  for (const Light& light : lights) sum += choice * pdf_li(light, x, wi);
  return sum;
}

// The one-sample direct light of stage 08 (direct_variant.h), MIS-weighted.
inline glm::vec3 light_sample(const RenderContext& context, const MisVariant& v, const SurfaceHit& hit, const Bsdf& bsdf,
                              const glm::vec3& wo, Sampler& sampler, bool bsdf_sample_follows) {
  const std::optional<DirectSample> s = unblocked_light_sample(context, DirectVariant{}, hit, bsdf, wo, sampler);
  if (!s) return glm::vec3(0.0f);
  const float pdf = s->light.pdf * s->choice;
  float weight = 1.0f;
  if ((!s->light.is_delta || v.delta_weighted) && (bsdf_sample_follows || v.last_vertex_weighted))
    weight = heuristic(v, pdf, bsdf_pdf(bsdf, hit.geometric_normal, wo, s->light.direction));
  return light_contribution(hit, *s, pdf, weight);
}

inline glm::vec3 path_radiance_variant(const RenderContext& context, const Ray& camera_ray, Sampler& sampler,
                                       const MisVariant& v) {
  glm::vec3 radiance(0.0f), throughput(1.0f);
  Ray ray = camera_ray;
  bool previous_specular = !v.camera_hit_weighted;
  float previous_pdf = 0.0f;
  glm::vec3 previous_point(0.0f);
  for (int depth = 0;; ++depth) {
    const std::optional<SurfaceHit> hit = context.geometry.intersect(ray);
    if (!hit) return radiance + throughput * context.scene.background;
    const Material& material = context.scene.materials[hit->material];
    const glm::vec3 wo = -glm::normalize(ray.direction);
    const glm::vec3 emitted = emitted_radiance(material, *hit, ray.direction);
    if (emitted != glm::vec3(0.0f)) {
      float weight = 1.0f;
      if (!previous_specular && !v.emission_unweighted)
        weight = heuristic(v, previous_pdf, light_density(context, v, previous_point, -wo));
      radiance += throughput * emitted * weight;
    }
    const Bsdf bsdf = bsdf_of(material, diffuse_color_at(material, *hit));
    const bool follows = depth < context.max_depth;
    if (!bsdf.is_specular()) radiance += throughput * light_sample(context, v, *hit, bsdf, wo, sampler, follows);
    if (!follows) return radiance;
    const float p = context.continue_probability(depth, throughput);
    if (p < 1.0f) {
      if (sampler.get_1d() >= p) return radiance;
      throughput /= p;
    }
    const float u_lobe = sampler.get_1d();
    const glm::vec2 u = sampler.get_2d();
    const std::optional<BsdfSample> sample = bsdf_sample_f(bsdf, hit->geometric_normal, wo, u_lobe, u);
    if (!sample) return radiance;
    throughput *= sample->f * (std::fabs(glm::dot(hit->geometric_normal, sample->wi)) / sample->pdf);
    if (throughput == glm::vec3(0.0f)) return radiance;
    previous_specular = sample->is_specular && !v.specular_hit_weighted;
    previous_pdf = sample->pdf;
    previous_point = hit->point;
    ray = spawn_ray(*hit, sample->wi);
  }
}

}  // namespace raylab::submission

// The submission's functions: `#define MIS_VARIANT(v) ...flags...` before including this.
namespace raylab {
namespace submission {
inline const MisVariant& variant() {
  static const MisVariant v = [] {
    MisVariant flags;
    MIS_VARIANT(flags);
    return flags;
  }();
  return v;
}
}  // namespace submission
float power_heuristic(int count_f, float pdf_f, int count_g, float pdf_g) {
  const submission::MisVariant& v = submission::variant();
  const float n_f = static_cast<float>(count_f), n_g = static_cast<float>(count_g);
  if (v.textbook_heuristic) return pdf_f * pdf_f / (pdf_f * pdf_f + pdf_g * pdf_g);
  if (v.counts_outside_square) {
    if (!(pdf_f > 0.0f)) return 0.0f;
    return n_f * pdf_f * pdf_f / (n_f * pdf_f * pdf_f + n_g * pdf_g * pdf_g);
  }
  if (v.half_weights) return submission::heuristic(submission::MisVariant{}, n_f * pdf_f, n_g * pdf_g);
  if (v.other_weight) {
    const float f = n_f * pdf_f, g = n_g * pdf_g;
    if (std::isinf(f)) return 1.0f;
    if (!(f > 0.0f)) return 0.0f;
    return g * g / (f * f + g * g);
  }
  return submission::heuristic(v, n_f * pdf_f, n_g * pdf_g);
}
glm::vec3 path_radiance_mis(const RenderContext& context, const Ray& camera_ray, Sampler& sampler) {
  return submission::path_radiance_variant(context, camera_ray, sampler, submission::variant());
}
}  // namespace raylab
