// Grader self-test submission (stage 10_microfacet): a correct implementation written another
// way: D and G1 in their tan^2 forms, the Fresnel power by std::pow, f without calling D and G1,
// the half vector's theta from the second number and phi from the first (1 - u), wi's density
// from the half vector written out. Full marks.
#include "raylab/stages/10_microfacet.h"

#include <algorithm>
#include <cmath>

namespace raylab {
namespace {
constexpr float kPiHere = 3.14159265358979f;

float tan2_of(float cos_theta) { return (1.0f - cos_theta * cos_theta) / (cos_theta * cos_theta); }
}  // namespace

float ggx_distribution(const glm::vec3& half_vector, float alpha) {
  if (half_vector.z <= 0.0f) return 0.0f;
  const float c2 = half_vector.z * half_vector.z, a2 = alpha * alpha;
  const float s = a2 + tan2_of(half_vector.z);
  return a2 / (kPiHere * c2 * c2 * s * s);
}

float ggx_smith_g1(const glm::vec3& direction, float alpha) {
  if (direction.z <= 0.0f) return 0.0f;
  if (direction.z >= 1.0f) return 1.0f;
  return 2.0f / (1.0f + std::sqrt(1.0f + alpha * alpha * tan2_of(direction.z)));
}

glm::vec3 microfacet_f(const glm::vec3& wo, const glm::vec3& wi, float alpha, const glm::vec3& specular_color) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
  const glm::vec3 h = glm::normalize(wi + wo);
  const float a2 = alpha * alpha, c2 = h.z * h.z;
  const float k = (a2 - 1.0f) * c2 + 1.0f;
  const float d = a2 / (kPiHere * k * k);
  auto lambda_term = [&](float c) { return std::sqrt(a2 + (1.0f - a2) * c * c); };
  // G1(wo) G1(wi) / (4 cos_o cos_i) = 1 / ((cos_o + L(wo)) (cos_i + L(wi)))
  const float visibility = 1.0f / ((wo.z + lambda_term(wo.z)) * (wi.z + lambda_term(wi.z)));
  const float weight = std::pow(1.0f - std::min(1.0f, glm::dot(wo, h)), 5.0f);
  return (specular_color * (1.0f - weight) + glm::vec3(weight)) * (d * visibility);
}

glm::vec3 sample_ggx_half_vector(glm::vec2 uniform_random, float alpha) {
  const float u = 1.0f - uniform_random.y;  // in (0, 1]
  const float cos2 = u / (u + alpha * alpha * (1.0f - u));  // tan^2 = alpha^2 (1 - u) / u
  const float cos_theta = std::sqrt(cos2), sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos2));
  const float phi = 2.0f * kPiHere * uniform_random.x;
  return glm::vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

float ggx_half_vector_pdf(const glm::vec3& half_vector, float alpha) {
  return half_vector.z > 0.0f ? ggx_distribution(half_vector, alpha) * half_vector.z : 0.0f;
}

glm::vec3 sample_microfacet_wi(const glm::vec3& wo, glm::vec2 uniform_random, float alpha) {
  const glm::vec3 h = sample_ggx_half_vector(uniform_random, alpha);
  return glm::reflect(-wo, h);
}

float microfacet_pdf(const glm::vec3& wo, const glm::vec3& wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const glm::vec3 h = glm::normalize(wo + wi);
  return ggx_distribution(h, alpha) * h.z / (4.0f * glm::dot(wi, h));
}

}  // namespace raylab
