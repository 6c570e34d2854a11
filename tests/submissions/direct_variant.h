// Grader self-test submissions of stage 08_direct_light share this file: each one sets the flags
// of one common mistake (or of a correct variant) and gets the stage's five functions with it, the
// reference's (solutions/08_direct_light) wherever no flag changes them, so that a submission file
// says only what it changes:
//   #define DIRECT_VARIANT(v) v.divide_by_choice = false
//   #include "direct_variant.h"
// Without DIRECT_VARIANT it defines no stage function, only the one-sample estimator's pieces
// (raylab::submission), which mis_variant.h samples its lights with.
#pragma once

#ifdef DIRECT_VARIANT
// The reference's functions under other names, for the flags that keep them.
#define point_light_intensity reference_point_light_intensity
#define point_light_irradiance reference_point_light_irradiance
#define lambertian_f reference_lambertian_f
#define area_pdf_to_solid_angle reference_area_pdf_to_solid_angle
#define estimate_direct_light reference_estimate_direct_light
#include "../../solutions/08_direct_light/direct_light.cpp"
#undef point_light_intensity
#undef point_light_irradiance
#undef lambertian_f
#undef area_pdf_to_solid_angle
#undef estimate_direct_light
#endif

#include "raylab/bsdf.h"
#include "raylab/lights.h"
#include "raylab/math.h"
#include "raylab/shading.h"
#include "raylab/stages/08_direct_light.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <optional>
#include <vector>

namespace raylab::submission {

struct DirectVariant {
  // Mistakes.
  bool intensity_over_pi = false;  // point_light_intensity: power / pi, not / (4 pi)
  bool irradiance_cosine = true;   // false: point_light_irradiance I / d^2, the cosine missing
  bool lambertian_pi = true;       // false: lambertian_f = albedo, 1 / pi missing
  bool pdf_converted = true;       // false: area_pdf_to_solid_angle returns the area pdf as it is
  bool divide_by_choice = true;    // false: the light's sample not divided by the probability of choosing it
  bool shadow_ray = true;          // false: no shadow ray, light passes through everything
  bool shadow_ray_stops = true;    // false: the shadow ray a unit direction, t_max left at infinity
  bool shadow_ray_offset = true;   // false: the shadow ray starts at hit.point itself
  bool f_is_albedo = false;        // true: the estimator's own f = the albedo, not bsdf_f (1 / pi missing)
  bool intensity_grey = false;     // point_light_intensity: every channel from the red one's power
  bool irradiance_squared = true;  // false: point_light_irradiance I cos / d, the distance not squared
  bool irradiance_behind_zero = true;  // false: point_light_irradiance negative for a light behind the surface
  bool light_from_behind = false;  // the estimator weighs a light sample behind the surface by |cos| (lit)
  bool check_no_lights = true;     // false: lights.choose() called on an empty light list
  bool own_random_numbers = false; // true: the light's point from rand(), not from sampler.get_2d()
  bool retry_without_sample = false;  // sample_li's nullopt answered by drawing new numbers, up to 16 times
  // Correct variants.
  bool lights_by_power = false;    // the light chosen with probability proportional to its power
  // Hostile.
  bool noise_hides_bias = false;   // with several lights, the estimate times 201 or -199 at random
                                   // (a factor of mean 1): noise to widen the mean tests
};

// The light that u in [0, 1) chooses and the probability of choosing it: uniformly (LightSet's
// choose), or by power (nullopt when no light has any). Requires !lights.empty().
inline std::optional<std::size_t> choose_light(const LightSet& lights, const DirectVariant& v, float u,
                                               float* probability) {
  if (!v.lights_by_power) return lights.choose(u, probability);
  auto power_of = [](const Light& light) {
    const glm::vec3 power = light_power(light);
    return power.x + power.y + power.z;
  };
  float total = 0.0f;
  for (const Light& light : lights.lights()) total += power_of(light);
  if (!(total > 0.0f)) return std::nullopt;
  const float scaled = u * total;
  std::size_t chosen = lights.size() - 1;
  float running = 0.0f;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    running += power_of(lights[i]);
    if (scaled < running) {
      chosen = i;
      break;
    }
  }
  *probability = power_of(lights[chosen]) / total;
  return chosen;
}

// One light sample from the hit that reaches it: the light chosen with probability `choice`, a
// point on it, the BSDF towards it. nullopt when it gives no light (none to choose, the light
// behind the surface, an occluder between them).
// Two numbers in [0, 1) from the C library's rand(), as a student who does not use the sampler
// might draw them.
inline glm::vec2 rand_pair() {
  const auto next = [] { return std::min(static_cast<float>(std::rand() / (RAND_MAX + 1.0)), 0x1.fffffep-1f); };
  const float a = next();
  return glm::vec2(a, next());
}

struct DirectSample {
  LightSample light;
  float choice = 0.0f;
  glm::vec3 f{0.0f};
};

inline std::optional<DirectSample> unblocked_light_sample(const RenderContext& context, const DirectVariant& v,
                                                          const SurfaceHit& hit, const Bsdf& bsdf,
                                                          const glm::vec3& wo, Sampler& sampler) {
  if (v.check_no_lights && context.lights.empty()) return std::nullopt;
  DirectSample sample;
  const std::optional<std::size_t> chosen = choose_light(context.lights, v, sampler.get_1d(), &sample.choice);
  if (!chosen) return std::nullopt;
  std::optional<LightSample> light =
      sample_li(context.lights[*chosen], hit.point, v.own_random_numbers ? rand_pair() : sampler.get_2d());
  for (int retry = 0; v.retry_without_sample && !light && retry < 16; ++retry)
    light = sample_li(context.lights[*chosen], hit.point, sampler.get_2d());
  if (!light) return std::nullopt;
  sample.light = *light;
  sample.f = bsdf_f(bsdf, hit.geometric_normal, wo, light->direction);
  if (v.f_is_albedo && sample.f != glm::vec3(0.0f)) sample.f = bsdf.albedo;
  if (v.light_from_behind && sample.f == glm::vec3(0.0f)) sample.f = bsdf.albedo / kPi;  // f without its side test
  if (sample.f == glm::vec3(0.0f)) return std::nullopt;
  if (!v.shadow_ray) return sample;
  Ray shadow;
  shadow.origin = v.shadow_ray_offset ? offset_ray_origin(hit, light->direction) : hit.point;
  if (v.shadow_ray_stops) {
    shadow.direction = light->point - shadow.origin;  // to just short of the light's point
    shadow.t_max = 1.0f - 1e-4f;
  } else {
    shadow.direction = light->direction;  // the mistake: on past the light's point, into the light
  }
  if (context.geometry.occluded(shadow)) return std::nullopt;
  return sample;
}

// The sample's light, weight f L |cos| / pdf, with `pdf` the density of the sample's direction.
inline glm::vec3 light_contribution(const SurfaceHit& hit, const DirectSample& sample, float pdf, float weight = 1.0f) {
  return weight * sample.f * sample.light.radiance *
         (std::fabs(glm::dot(hit.geometric_normal, sample.light.direction)) / pdf);
}

inline glm::vec3 estimate_direct_light_variant(const RenderContext& context, const DirectVariant& v,
                                               const SurfaceHit& hit, const Bsdf& bsdf, const glm::vec3& wo,
                                               Sampler& sampler) {
  const std::optional<DirectSample> sample = unblocked_light_sample(context, v, hit, bsdf, wo, sampler);
  if (!sample) return glm::vec3(0.0f);
  const glm::vec3 value =
      light_contribution(hit, *sample, v.divide_by_choice ? sample->light.pdf * sample->choice : sample->light.pdf);
  if (v.noise_hides_bias && context.lights.size() > 1) return value * (sampler.get_1d() < 0.5f ? 201.0f : -199.0f);
  return value;
}

}  // namespace raylab::submission

#ifdef DIRECT_VARIANT
// The submission's five functions.
namespace raylab {
namespace submission {
inline constexpr DirectVariant kDirectVariant = [] {
  DirectVariant flags;
  DIRECT_VARIANT(flags);
  return flags;
}();
}  // namespace submission

glm::vec3 point_light_intensity(const glm::vec3& power) {
  if (submission::kDirectVariant.intensity_over_pi) return power / kPi;
  if (submission::kDirectVariant.intensity_grey) return glm::vec3(power.x / (4.0f * kPi));
  return reference_point_light_intensity(power);
}

glm::vec3 point_light_irradiance(const glm::vec3& intensity, const glm::vec3& light_position, const glm::vec3& point,
                                 const glm::vec3& normal) {
  const submission::DirectVariant& v = submission::kDirectVariant;
  if (v.irradiance_cosine && v.irradiance_squared && v.irradiance_behind_zero)
    return reference_point_light_irradiance(intensity, light_position, point, normal);
  const glm::vec3 to_light = light_position - point;
  const float distance = glm::length(to_light);
  const float cosine = glm::dot(normal, to_light) / distance;
  if (v.irradiance_behind_zero && cosine <= 0.0f) return glm::vec3(0.0f);
  const float falloff = v.irradiance_squared ? distance * distance : distance;
  return intensity * ((v.irradiance_cosine ? cosine : 1.0f) / falloff);
}

glm::vec3 lambertian_f(const glm::vec3& albedo) {
  return submission::kDirectVariant.lambertian_pi ? reference_lambertian_f(albedo) : albedo;
}

float area_pdf_to_solid_angle(float pdf_area, float distance, float cos_at_light) {
  if (submission::kDirectVariant.pdf_converted)
    return reference_area_pdf_to_solid_angle(pdf_area, distance, cos_at_light);
  return pdf_area;
}

// With no flag of its own set, the reference's steps one for one (the same numbers drawn).
glm::vec3 estimate_direct_light(const RenderContext& context, const SurfaceHit& hit, const Bsdf& bsdf,
                                const glm::vec3& wo, Sampler& sampler) {
  return submission::estimate_direct_light_variant(context, submission::kDirectVariant, hit, bsdf, wo, sampler);
}
}  // namespace raylab
#endif
