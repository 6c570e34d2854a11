// Grader self-test submissions of stage 10_microfacet share this implementation: each one sets
// the flags of its mistakes and defines the stage's functions with them, so that a submission
// file says only what it changes. Every function calls the others as a student's would (f calls
// D and G1, wi's sampler and density the half vector's), so a wrong D also shows in f.
#pragma once

#include "raylab/stages/10_microfacet.h"

#include <algorithm>
#include <cmath>

namespace raylab::submission {

struct MicrofacetVariant {
  bool d_alpha_squared_first = false;   // D with alpha^2 in place of alpha (a "roughness" squared)
  bool d_no_inverse_pi = false;         // D without 1 / pi
  bool f_no_masking = false;            // f without G1(wo) G1(wi)
  bool f_fresnel_at_normal = false;     // Schlick's Fresnel at wi.z instead of dot(wi, h)
  bool half_vector_no_sqrt = false;     // tan(theta) = alpha u / (1 - u)
  bool half_vector_alpha_squared = false;  // the half vectors sampled with alpha^2 in place of alpha
  bool pdf_no_jacobian = false;         // microfacet_pdf = the half vector's density
  bool horizon_checks = true;           // false: D, G1, f and both densities never return 0 below the surface
  bool g1_tan_not_squared = false;      // G1 = 2 / (1 + sqrt(1 + alpha^2 tan(theta)))
  bool g1_no_factor_two = false;        // G1 = 1 / (1 + sqrt(1 + alpha^2 tan^2(theta))): 1/2 along the normal
  bool half_vector_below = false;       // the half vector's z negated (below the surface)
  bool wi_visible_normals = false;      // sample_microfacet_wi mirrors wo about a visible normal (Heitz 2018)
  bool wi_flipped_above = false;        // a wi below the surface mirrored above it instead of returned
  bool azimuth_normalised = false;      // the half vector's horizontal part as normalize(sin_theta (cos phi, sin phi))
                                        // times sin_theta: NaN where sin_theta = 0 (u.x = 0)
};

inline MicrofacetVariant microfacet_variant() {
  MicrofacetVariant v;
  MICROFACET_VARIANT(v);
  return v;
}

}  // namespace raylab::submission

namespace raylab {

float ggx_distribution(const glm::vec3& half_vector, float alpha) {
  const submission::MicrofacetVariant v = submission::microfacet_variant();
  const float c = half_vector.z;
  if (v.horizon_checks && !(c > 0.0f)) return 0.0f;
  const float a = v.d_alpha_squared_first ? alpha * alpha : alpha;
  const float a2 = a * a, k = (a2 - 1.0f) * c * c + 1.0f;
  return a2 / ((v.d_no_inverse_pi ? 1.0f : 3.14159265f) * k * k);
}

float ggx_smith_g1(const glm::vec3& direction, float alpha) {
  const submission::MicrofacetVariant v = submission::microfacet_variant();
  const float c = direction.z;
  if (v.horizon_checks && !(c > 0.0f)) return 0.0f;
  const float c2 = std::min(1.0f, c * c);
  const float tan2 = (1.0f - c2) / c2;
  return (v.g1_no_factor_two ? 1.0f : 2.0f) /
         (1.0f + std::sqrt(1.0f + alpha * alpha * (v.g1_tan_not_squared ? std::sqrt(tan2) : tan2)));
}

glm::vec3 microfacet_f(const glm::vec3& wo, const glm::vec3& wi, float alpha, const glm::vec3& specular_color) {
  const submission::MicrofacetVariant v = submission::microfacet_variant();
  if (v.horizon_checks && (!(wo.z > 0.0f) || !(wi.z > 0.0f))) return glm::vec3(0.0f);
  const glm::vec3 h = glm::normalize(wo + wi);
  const float m = 1.0f - std::clamp(v.f_fresnel_at_normal ? wi.z : glm::dot(wi, h), 0.0f, 1.0f);
  const glm::vec3 fresnel = specular_color + (glm::vec3(1.0f) - specular_color) * (m * m * m * m * m);
  const float masking = v.f_no_masking ? 1.0f : ggx_smith_g1(wo, alpha) * ggx_smith_g1(wi, alpha);
  return fresnel * (ggx_distribution(h, alpha) * masking / (4.0f * wo.z * wi.z));
}

glm::vec3 sample_ggx_half_vector(glm::vec2 uniform_random, float alpha) {
  const submission::MicrofacetVariant v = submission::microfacet_variant();
  const float u = uniform_random.x;
  if (v.half_vector_alpha_squared) alpha = alpha * alpha;
  const float tan2 = v.half_vector_no_sqrt ? std::pow(alpha * u / (1.0f - u), 2.0f) : alpha * alpha * u / (1.0f - u);
  const float cos_theta = 1.0f / std::sqrt(1.0f + tan2);
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float phi = 6.28318531f * uniform_random.y;
  glm::vec2 horizontal = sin_theta * glm::vec2(std::cos(phi), std::sin(phi));
  if (v.azimuth_normalised) horizontal = glm::normalize(horizontal) * sin_theta;
  return glm::vec3(horizontal, v.half_vector_below ? -cos_theta : cos_theta);
}

float ggx_half_vector_pdf(const glm::vec3& half_vector, float alpha) {
  const submission::MicrofacetVariant v = submission::microfacet_variant();
  return half_vector.z > 0.0f || !v.horizon_checks ? ggx_distribution(half_vector, alpha) * half_vector.z : 0.0f;
}

// A normal of GGX's visible normals seen from wo: wo stretched to the hemisphere of alpha 1, a
// point of the projected disk (the half of it behind the stretched wo squeezed), lifted onto the
// hemisphere and unstretched (Heitz, "Sampling the GGX Distribution of Visible Normals", 2018).
inline glm::vec3 visible_normal(const glm::vec3& wo, glm::vec2 u, float alpha) {
  const glm::vec3 v = glm::normalize(glm::vec3(alpha * wo.x, alpha * wo.y, wo.z));
  const float length_xy = std::sqrt(v.x * v.x + v.y * v.y);
  const glm::vec3 t1 = length_xy > 0.0f ? glm::vec3(-v.y, v.x, 0.0f) / length_xy : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 t2 = glm::cross(v, t1);
  const float r = std::sqrt(u.x), phi = 6.28318531f * u.y;
  const float p1 = r * std::cos(phi), s = 0.5f * (1.0f + v.z);
  const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
  const glm::vec3 n = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * v;
  return glm::normalize(glm::vec3(alpha * n.x, alpha * n.y, std::max(0.0f, n.z)));
}

glm::vec3 sample_microfacet_wi(const glm::vec3& wo, glm::vec2 uniform_random, float alpha) {
  const glm::vec3 h = submission::microfacet_variant().wi_visible_normals ? visible_normal(wo, uniform_random, alpha)
                                                                         : sample_ggx_half_vector(uniform_random, alpha);
  const glm::vec3 wi = 2.0f * glm::dot(wo, h) * h - wo;
  return submission::microfacet_variant().wi_flipped_above && wi.z < 0.0f ? glm::vec3(wi.x, wi.y, -wi.z) : wi;
}

float microfacet_pdf(const glm::vec3& wo, const glm::vec3& wi, float alpha) {
  const submission::MicrofacetVariant v = submission::microfacet_variant();
  if (v.horizon_checks && (!(wo.z > 0.0f) || !(wi.z > 0.0f))) return 0.0f;
  const glm::vec3 h = glm::normalize(wo + wi);
  return ggx_half_vector_pdf(h, alpha) / (v.pdf_no_jacobian ? 1.0f : 4.0f * std::fabs(glm::dot(wo, h)));
}

}  // namespace raylab
