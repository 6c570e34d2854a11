// Grader self-test submissions of stage 09_path share this path tracer: each one sets the flags
// of one common mistake (or of a correct variant) and defines path_radiance with it, so that a
// submission file says only what it changes.
#pragma once

#include "direct_variant.h"

#include "raylab/bsdf.h"
#include "raylab/lights.h"
#include "raylab/sampling.h"
#include "raylab/shading.h"
#include "raylab/stages/07_sampling.h"
#include "raylab/stages/08_direct_light.h"
#include "raylab/stages/09_path.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace raylab::submission {

struct PathVariant {
  // Mistakes.
  bool divide_by_roulette = true;         // false: roulette not divided by p
  bool emission_after_diffuse = false;    // true: emission counted twice
  bool emission_at_camera_hit = true;     // false: the light black when seen directly
  bool cosine = true;                     // false: the cosine missing from the bounce weight
  bool f_is_albedo = false;               // true: a diffuse bounce weighed with f = the albedo (1 / pi missing)
  bool multiply_throughput = true;        // false: the throughput never multiplied by the bounce weight
  float next_ray_offset = 0.0f;           // > 0: the next ray starts this far off the surface along its
                                          // normal (GAMES101 assignment 7's EPSILON), not with spawn_ray
  bool pdf_from_bsdf_pdf = false;         // true: divides by bsdf_pdf (0 for mirrors and glass)
  bool one_surface_short = false;         // true: a loop depth < max_depth (the last surface left out)
  bool shadow_ray_hits_light = false;     // true: its own direct light, whose shadow ray runs to infinity
                                          // (a unit direction, t_max infinite) and so hits the light itself
  bool play_roulette = true;              // false: no Russian roulette (every path goes on to max_depth)
  bool emission_after_specular = true;    // false: no emission counted after a mirror or glass bounce
  bool own_random_numbers = false;        // true: the bounce direction from rand(), not from sampler.get_2d()
  bool background = true;                 // false: black where nothing is hit, not the scene's background
  // Correct variants.
  bool uniform_hemisphere = false;        // diffuse bounces sampled uniformly (pdf 1 / (2 pi))
  bool throughput_roulette = false;       // roulette by the throughput, p = min(1, max channel)
};

// The direct light as stage 08's estimate_direct_light computes it, written in the path tracer
// itself as GAMES101's castRay does (direct_variant.h's estimator), with the shadow ray of `v`.
inline glm::vec3 direct_light_variant(const RenderContext& context, const SurfaceHit& hit, const Bsdf& bsdf,
                                      const glm::vec3& wo, Sampler& sampler, const PathVariant& v) {
  DirectVariant direct;
  direct.shadow_ray_stops = !v.shadow_ray_hits_light;
  return estimate_direct_light_variant(context, direct, hit, bsdf, wo, sampler);
}

inline glm::vec3 path_radiance_variant(const RenderContext& context, const Ray& camera_ray, Sampler& sampler,
                                       const PathVariant& v) {
  const Scene& scene = context.scene;
  glm::vec3 radiance(0.0f), throughput(1.0f);
  Ray ray = camera_ray;
  bool previous_specular = true;  // the camera counts as specular: its hit's emission is seen
  for (int depth = 0;; ++depth) {
    if (v.one_surface_short && depth >= context.max_depth) return radiance;
    const std::optional<SurfaceHit> hit = context.geometry.intersect(ray);
    if (!hit) return v.background ? radiance + throughput * scene.background : radiance;
    const Material& material = scene.materials[hit->material];
    const glm::vec3 wo = -glm::normalize(ray.direction);
    const glm::vec3 emitted = emitted_radiance(material, *hit, ray.direction);
    if (depth == 0) {
      if (v.emission_at_camera_hit) radiance += throughput * emitted;
    } else if ((previous_specular && v.emission_after_specular) || v.emission_after_diffuse) {
      radiance += throughput * emitted;
    }
    const Bsdf bsdf = bsdf_of(material, diffuse_color_at(material, *hit));
    const glm::vec3& normal = hit->geometric_normal;
    if (!bsdf.is_specular())
      radiance += throughput * (v.shadow_ray_hits_light ? direct_light_variant(context, *hit, bsdf, wo, sampler, v)
                                                        : estimate_direct_light(context, *hit, bsdf, wo, sampler));
    if (depth >= context.max_depth) return radiance;
    float p = context.continue_probability(depth, throughput);
    if (v.throughput_roulette) p = std::min(1.0f, std::max({throughput.x, throughput.y, throughput.z, 0.05f}));
    if (p < 1.0f && v.play_roulette) {
      if (sampler.get_1d() >= p) return radiance;
      if (v.divide_by_roulette) throughput /= p;
    }
    const float u_lobe = sampler.get_1d();
    const glm::vec2 u = v.own_random_numbers ? rand_pair() : sampler.get_2d();
    glm::vec3 f, wi;
    float pdf = 0.0f;
    bool specular = bsdf.is_specular();
    if (v.uniform_hemisphere && !specular) {
      const glm::vec3 facing = glm::dot(normal, wo) > 0.0f ? normal : -normal;
      const glm::vec3 local = sample_uniform_hemisphere(u);
      wi = glm::normalize(Frame(facing).to_world(local));
      pdf = uniform_hemisphere_pdf(local);
      f = bsdf_f(bsdf, normal, wo, wi);
      if (!(pdf > 0.0f) || f == glm::vec3(0.0f)) return radiance;
    } else {
      const std::optional<BsdfSample> sample = bsdf_sample_f(bsdf, normal, wo, u_lobe, u);
      if (!sample) return radiance;
      f = v.f_is_albedo && !sample->is_specular ? bsdf.albedo : sample->f;
      wi = sample->wi;
      pdf = v.pdf_from_bsdf_pdf ? bsdf_pdf(bsdf, normal, wo, wi) : sample->pdf;
      specular = sample->is_specular;
    }
    const float cosine = v.cosine ? std::fabs(glm::dot(normal, wi)) : 1.0f;
    if (v.multiply_throughput) throughput *= f * (cosine / pdf);
    if (throughput == glm::vec3(0.0f)) return radiance;
    previous_specular = specular;
    if (v.next_ray_offset > 0.0f) {
      const glm::vec3 side = glm::dot(normal, wi) > 0.0f ? normal : -normal;
      ray = make_ray(hit->point + v.next_ray_offset * side, wi);
    } else {
      ray = spawn_ray(*hit, wi);
    }
  }
}

}  // namespace raylab::submission

// The submission's path_radiance: `#define PATH_VARIANT { ...flags... }` before including this.
namespace raylab {
glm::vec3 path_radiance(const RenderContext& context, const Ray& camera_ray, Sampler& sampler) {
  static const submission::PathVariant variant = [] {
    submission::PathVariant v;
    PATH_VARIANT(v);
    return v;
  }();
  return submission::path_radiance_variant(context, camera_ray, sampler, variant);
}
}  // namespace raylab
