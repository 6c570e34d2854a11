#include "raylab/bsdf.h"

#include "raylab/sampling.h"
#include "raylab/shading.h"
#include "raylab/stages/07_sampling.h"
#include "raylab/stages/08_direct_light.h"
#include "raylab/stages/10_microfacet.h"
#include "raylab/trace_recorder.h"

#include <algorithm>
#include <cmath>

namespace raylab {

glm::vec3 bsdf_f(const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo, const glm::vec3& wi) {
  if (bsdf.is_specular()) return glm::vec3(0.0f);
  const float cos_o = glm::dot(normal, wo), cos_i = glm::dot(normal, wi);
  if (!(cos_o * cos_i > 0.0f)) return glm::vec3(0.0f);  // wi on the other side: no transmission
  if (bsdf.kind == BsdfKind::Lambertian) return lambertian_f(bsdf.albedo);
  const Frame frame(cos_o > 0.0f ? normal : -normal);  // on wo's side, as bsdf_sample_f
  return microfacet_f(frame.to_local(wo), frame.to_local(wi), bsdf.alpha, bsdf.reflectance);
}

float bsdf_pdf(const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo, const glm::vec3& wi) {
  if (bsdf.is_specular()) return 0.0f;
  const float cos_o = glm::dot(normal, wo), cos_i = glm::dot(normal, wi);
  if (!(cos_o * cos_i > 0.0f)) return 0.0f;
  const Frame frame(cos_o > 0.0f ? normal : -normal);  // on wo's side, as bsdf_sample_f
  if (bsdf.kind == BsdfKind::Lambertian) return cosine_hemisphere_pdf(frame.to_local(wi));
  return microfacet_pdf(frame.to_local(wo), frame.to_local(wi), bsdf.alpha);
}

namespace {

// bsdf_sample_f's work: fills `sample` (as constructed) and returns true, or returns false
// where there is no sample.
bool sample_f_into(BsdfSample& sample, const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo, float u_lobe,
                   glm::vec2 u) {
  const float cos_o = glm::dot(normal, wo);
  if (cos_o == 0.0f || !std::isfinite(cos_o)) return false;
  const glm::vec3 facing_normal = cos_o > 0.0f ? normal : -normal;  // on wo's side
  switch (bsdf.kind) {
    case BsdfKind::Lambertian: {
      const glm::vec3 local = sample_cosine_hemisphere(u);
      if (!(local.z > 0.0f)) return false;  // on the rim: no density
      // As long as `local` is (stage 07's sample_cosine_hemisphere returns unit vectors), unit to
      // within rounding: a vector turned by an orthonormal frame keeps its length. Not normalized
      // again, as pbrt-v4 does not: the next ray waits for every step of this one. (f |cos| / pdf
      // does not depend on the length: cos_i is local.z, as the pdf is.)
      sample.wi = Frame(facing_normal).to_world(local);
      const float cos_i = glm::dot(facing_normal, sample.wi);
      if (!(cos_i > 0.0f)) return false;
      sample.f = lambertian_f(bsdf.albedo);
      sample.pdf = cosine_hemisphere_pdf(local);
      return sample.pdf > 0.0f && std::isfinite(sample.pdf);
    }
    case BsdfKind::Microfacet: {
      const Frame frame(facing_normal);
      const glm::vec3 local_wo = frame.to_local(wo);
      if (!(local_wo.z > 0.0f)) return false;  // rounding at a grazing wo
      const glm::vec3 local_wi = sample_microfacet_wi(local_wo, u, bsdf.alpha);
      if (!(local_wi.z > 0.0f)) return false;  // mirrored below the surface: no sample
      sample.wi = glm::normalize(frame.to_world(local_wi));
      if (!(glm::dot(facing_normal, sample.wi) > 0.0f)) return false;
      // f and pdf of the direction returned, as bsdf_f and bsdf_pdf compute them (the same bits:
      // near a shiny lobe's peak a rounding of wi changes D by more than float precision).
      const glm::vec3 returned_wi = frame.to_local(sample.wi);
      sample.f = microfacet_f(local_wo, returned_wi, bsdf.alpha, bsdf.reflectance);
      sample.pdf = microfacet_pdf(local_wo, returned_wi, bsdf.alpha);
      return sample.pdf > 0.0f && std::isfinite(sample.pdf);
    }
    case BsdfKind::Mirror: {
      sample.wi = glm::normalize(reflect(-wo, facing_normal));
      const float weight = bsdf.fresnel_ior > 0.0f ? fresnel_reflectance(-wo, normal, bsdf.fresnel_ior) : 1.0f;
      const float cos_i = std::fabs(glm::dot(normal, sample.wi));
      sample.f = bsdf.reflectance * (weight / cos_i);
      sample.pdf = 1.0f;
      sample.is_specular = true;
      return true;
    }
    case BsdfKind::Dielectric: {
      const glm::vec3 incident = -wo;
      const float reflectance = fresnel_reflectance(incident, normal, bsdf.ior);
      if (u_lobe < reflectance) {
        sample.wi = glm::normalize(reflect(incident, normal));
        sample.f = glm::vec3(reflectance / std::fabs(glm::dot(normal, sample.wi)));
        sample.pdf = reflectance;
      } else {
        const glm::vec3 refracted = refract(incident, normal, bsdf.ior);
        if (refracted == glm::vec3(0.0f)) return false;  // cannot happen: F = 1 there
        sample.wi = glm::normalize(refracted);
        const bool entering = cos_o > 0.0f;  // wo outside: the light comes from inside
        const float eta_ratio = entering ? 1.0f / bsdf.ior : bsdf.ior;  // eta_incident / eta_transmitted along the ray
        const float transmittance = 1.0f - reflectance;
        sample.f = glm::vec3(transmittance * eta_ratio * eta_ratio / std::fabs(glm::dot(normal, sample.wi)));
        sample.pdf = transmittance;
      }
      sample.is_specular = true;
      return sample.pdf > 0.0f;
    }
  }
  return false;
}

// bsdf_sample_f while a trace records (raylab/trace_recorder.h).
RAYLAB_RECORDED_VERSION std::optional<BsdfSample> bsdf_sample_f_recorded(const Bsdf& bsdf, const glm::vec3& normal,
                                                                         const glm::vec3& wo, float u_lobe,
                                                                         glm::vec2 u) {
  PausedRecording paused;
  return record_bsdf_sample(*paused.recorder, bsdf, normal, wo, u_lobe, u, bsdf_sample_f(bsdf, normal, wo, u_lobe, u));
}

}  // namespace

std::optional<BsdfSample> bsdf_sample_f(const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo,
                                        float u_lobe, glm::vec2 u) {
  // Filled where the caller reads it (one named return value), not copied there: see
  // SceneGeometry::intersect.
  std::optional<BsdfSample> result;
  if (RAYLAB_UNLIKELY(active_trace_recorder)) {
    result = bsdf_sample_f_recorded(bsdf, normal, wo, u_lobe, u);
    return result;
  }
  result.emplace();
  if (!sample_f_into(*result, bsdf, normal, wo, u_lobe, u)) result.reset();
  return result;
}

Bsdf bsdf_of(const Material& material, const glm::vec3& diffuse_color) {
  Bsdf bsdf;
  switch (material.kind) {
    case MaterialKind::Diffuse:
      bsdf.kind = BsdfKind::Lambertian;
      bsdf.albedo = diffuse_color;
      break;
    case MaterialKind::DiffuseGlossy:
      bsdf.kind = BsdfKind::Lambertian;
      bsdf.albedo = glm::min(glm::vec3(1.0f), material.kd * diffuse_color);
      break;
    case MaterialKind::Reflective:
      bsdf.kind = BsdfKind::Mirror;
      bsdf.fresnel_ior = material.index_of_refraction;
      break;
    case MaterialKind::Mirror:
      bsdf.kind = BsdfKind::Mirror;
      bsdf.reflectance = material.reflectance;
      break;
    case MaterialKind::ReflectiveRefractive:
      bsdf.kind = BsdfKind::Dielectric;
      bsdf.ior = material.index_of_refraction;
      break;
    case MaterialKind::Microfacet:
      bsdf.kind = BsdfKind::Microfacet;
      bsdf.alpha = material.alpha;
      bsdf.reflectance = material.reflectance;
      break;
  }
  return bsdf;
}

}  // namespace raylab
