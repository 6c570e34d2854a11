// BSDFs, in the shape of pbrt-v4's BSDF (f, Sample_f, PDF) and Nori's BSDF (eval, sample,
// pdf), as one value type dispatched by a switch (no virtual call per ray).
//
// Conventions: world-space unit directions, both pointing AWAY from the surface:
//   wo  towards the viewer (minus the incoming ray's direction),
//   wi  towards where the light comes from.
// `normal` is the surface's unit geometric normal, either side: surfaces are two-sided, and
// the side of wo decides "outside" for the Lambertian and the mirror; for the dielectric the
// normal's side is the outside (the side the index of refraction 1 is on).
//
// Lambertian  f = albedo / pi on wo's side (stage 08's lambertian_f), sampled cosine-weighted
//             (pdf = |cos| / pi).
// Mirror      perfect specular reflection, weight reflectance * Fresnel (fresnel_ior > 0: the
//             dielectric Fresnel reflectance of GAMES101's "reflective"; 0: none).
// Microfacet  a rough metal (stage 10's microfacet_f on wo's side), sampled by stage 10's
//             sample_microfacet_wi (pdf microfacet_pdf): not specular, so the integrators
//             sample the lights at it, as at a Lambertian surface.
// Dielectric  glass: reflection with probability F (Fresnel), refraction with 1 - F; the
//             refracted radiance is scaled by (eta_incident / eta_transmitted)^2 (pbrt-v4's
//             radiance transport).
// Specular lobes are deltas: f() and pdf() give 0 for them, and sample_f returns
// is_specular with f and pdf such that f |cos(wi)| / pdf is the lobe's weight (pbrt's rule),
// so that an integrator weighs every sample by f |cos| / pdf.
#pragma once

#include "raylab/math.h"
#include "raylab/scene.h"

#include <cstdint>
#include <optional>

namespace raylab {

enum class BsdfKind : std::uint8_t { Lambertian, Mirror, Dielectric, Microfacet };

struct Bsdf {
  BsdfKind kind = BsdfKind::Lambertian;
  glm::vec3 albedo{0.0f};       // Lambertian: in [0, 1] per channel
  glm::vec3 reflectance{1.0f};  // Mirror; Microfacet: at normal incidence (Schlick)
  float fresnel_ior = 0.0f;     // Mirror: 0 = no Fresnel weight
  float ior = 1.5f;             // Dielectric: inside / outside
  float alpha = 0.2f;           // Microfacet: GGX's roughness

  // A delta lobe (mirror, glass): no light sampling, f and pdf 0 for any given pair.
  bool is_specular() const { return kind == BsdfKind::Mirror || kind == BsdfKind::Dielectric; }
  // Reflects no light at all (a black diffuse surface, a metal of reflectance 0): nothing to sample.
  bool is_black() const {
    return (kind == BsdfKind::Lambertian && albedo == glm::vec3(0.0f)) ||
           (kind == BsdfKind::Microfacet && reflectance == glm::vec3(0.0f));
  }
};

struct BsdfSample {
  glm::vec3 f{0.0f};
  glm::vec3 wi{0.0f};
  float pdf = 0.0f;
  bool is_specular = false;
};

// The BSDF value for the pair of directions (0 for the specular kinds).
glm::vec3 bsdf_f(const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo, const glm::vec3& wi);

// Samples wi for wo. u_lobe in [0, 1) picks the dielectric's lobe, u in [0, 1)^2 the
// direction. nullopt when nothing is reflected (wo in the surface plane, zero weight).
std::optional<BsdfSample> bsdf_sample_f(const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo,
                                        float u_lobe, glm::vec2 u);

// The solid-angle density with which bsdf_sample_f gives wi (0 for the specular kinds).
float bsdf_pdf(const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo, const glm::vec3& wi);

// The BSDF of a material at a hit: diffuse and diffuse_glossy are Lambertian with albedo
// diffuse colour (times kd for diffuse_glossy: its Phong lobe is Whitted-only), reflective a
// Fresnel-weighted mirror, mirror a mirror of its reflectance, reflective_refractive a
// dielectric, microfacet the microfacet BSDF of its alpha and reflectance. `diffuse_color` is
// the material's colour at the hit (checkerboard included).
Bsdf bsdf_of(const Material& material, const glm::vec3& diffuse_color);

}  // namespace raylab
