// Reference solution, stage 10_microfacet (the GGX microfacet BSDF and its sampling). The
// contract is in assignments/10_microfacet/microfacet.cpp and docs/10_microfacet.md.
#include "raylab/stages/10_microfacet.h"

#include "raylab/math.h"

#include <algorithm>
#include <cmath>

namespace raylab {

float ggx_distribution(const glm::vec3& half_vector, float alpha) {
  const float cos_theta = half_vector.z;
  if (!(cos_theta > 0.0f)) return 0.0f;
  const float alpha2 = alpha * alpha;
  const float denominator = (alpha2 - 1.0f) * cos_theta * cos_theta + 1.0f;
  return alpha2 / (kPi * denominator * denominator);
}

float ggx_smith_g1(const glm::vec3& direction, float alpha) {
  const float cos_theta = direction.z;
  if (!(cos_theta > 0.0f)) return 0.0f;
  // 2 / (1 + sqrt(1 + alpha^2 tan^2)) times cos / cos: no division by cos^2, exact 1 at cos = 1.
  const float cos2 = std::min(1.0f, cos_theta * cos_theta);
  return 2.0f * cos_theta / (cos_theta + std::sqrt(alpha * alpha * (1.0f - cos2) + cos2));
}

glm::vec3 microfacet_f(const glm::vec3& wo, const glm::vec3& wi, float alpha, const glm::vec3& specular_color) {
  if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return glm::vec3(0.0f);
  const glm::vec3 sum = wo + wi;  // never 0: both above the surface
  const glm::vec3 h = sum / glm::length(sum);
  const float cos_d = std::clamp(glm::dot(wi, h), 0.0f, 1.0f);
  const float m = 1.0f - cos_d;
  const float m5 = (m * m) * (m * m) * m;
  const glm::vec3 fresnel = specular_color + (glm::vec3(1.0f) - specular_color) * m5;
  const float shape =
      ggx_distribution(h, alpha) * ggx_smith_g1(wo, alpha) * ggx_smith_g1(wi, alpha) / (4.0f * wo.z * wi.z);
  return fresnel * shape;
}

glm::vec3 sample_ggx_half_vector(glm::vec2 uniform_random, float alpha) {
  // The share of D(h) cos(theta_h) within theta is tan^2 / (alpha^2 + tan^2): set it to u and
  // solve, tan^2(theta) = alpha^2 u / (1 - u) (1 - u > 0: u < 1).
  const float u = uniform_random.x;
  const float tan2 = alpha * alpha * u / (1.0f - u);
  const float cos_theta = 1.0f / std::sqrt(1.0f + tan2);
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float phi = 2.0f * kPi * uniform_random.y;
  return glm::vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

float ggx_half_vector_pdf(const glm::vec3& half_vector, float alpha) {
  if (!(half_vector.z > 0.0f)) return 0.0f;
  return ggx_distribution(half_vector, alpha) * half_vector.z;
}

glm::vec3 sample_microfacet_wi(const glm::vec3& wo, glm::vec2 uniform_random, float alpha) {
  const glm::vec3 h = sample_ggx_half_vector(uniform_random, alpha);
  return 2.0f * glm::dot(wo, h) * h - wo;
}

float microfacet_pdf(const glm::vec3& wo, const glm::vec3& wi, float alpha) {
  if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
  const glm::vec3 sum = wo + wi;
  const glm::vec3 h = sum / glm::length(sum);
  // d(wi) = 4 |wo . h| d(h): mirroring about h doubles the angles (handout section 6).
  return ggx_half_vector_pdf(h, alpha) / (4.0f * std::fabs(glm::dot(wo, h)));
}

}  // namespace raylab
