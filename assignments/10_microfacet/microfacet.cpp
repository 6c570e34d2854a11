// Stage 10_microfacet (bonus): a rough metal, GGX microfacets.      Handout: docs/10_microfacet.md
//
// A rough surface is a carpet of tiny mirrors ("microfacets") whose normals scatter around the
// surface normal. Light from wi reaches the viewer at wo only through the facets whose normal
// is the half vector h = normalize(wo + wi). The BSDF multiplies how many facets face h (the
// distribution D), how many of them neither direction sees hidden (the masking G1, once for
// each direction) and how much a facet reflects (Fresnel F). Then you sample it: pick h where D
// is large and mirror wo about it, with the density of wi that this gives.
//
// CONVENTIONS (as stage 07)
//   Directions: unit glm::vec3 in a LOCAL frame whose z axis is the surface normal, so
//   v.z = cos(theta_v); "above the surface" is z > 0. wo (towards the viewer) and wi (towards
//   the light) both point AWAY from the surface. h = normalize(wo + wi).
//   alpha: GGX's roughness parameter, in (0, 1]. Use it as it is (do not square it first):
//   alpha = 0.05 is nearly a mirror, alpha = 1 very rough.
//   uniform_random: two independent numbers, each uniform in [0, 1) (0 can happen, 1 never).
//   Densities of directions are per steradian.
//
// READ docs/10_microfacet.md: section 1 (the microfacet model), 2 (D), 3 (G1), 4 (Fresnel and
//   f), 5 (sampling h), 6 (from h to wi: the factor 1 / (4 |wo . h|)), 7 (common mistakes, which
//   the autograder's hints name, and how to check).
//
// HOW TO CHECK
//   build/bin/autograder --stage 10_microfacet
//   build/bin/raylab render scenes/mis_plates.json -o plates.png --spp 64
//     (four metal plates from shiny to rough, four lights from small to big; with
//     --integrator mis your stage 09b weighs both samples)
#include "raylab/error.h"
#include "raylab/stages/10_microfacet.h"

namespace raylab {

// RETURN GGX's D(h) = alpha^2 / (pi ((alpha^2 - 1) cos^2(theta_h) + 1)^2), cos(theta_h) =
// half_vector.z; 0 when half_vector.z <= 0. Handout section 2 (check: at h = (0, 0, 1) it is
// 1 / (pi alpha^2)).
float ggx_distribution(const glm::vec3& half_vector, float alpha) {
  (void)half_vector;
  (void)alpha;
  // Delete the line below when you write the function (handout section 2).
  throw NotImplemented("ggx_distribution");
}

// RETURN Smith's masking G1(v) = 2 / (1 + sqrt(1 + alpha^2 tan^2(theta_v))), tan^2 = (1 - cos^2) /
// cos^2 with cos = direction.z; 1 along the normal, 0 when direction.z <= 0. Handout section 3.
float ggx_smith_g1(const glm::vec3& direction, float alpha) {
  (void)direction;
  (void)alpha;
  throw NotImplemented("ggx_smith_g1");
}

// RETURN f(wo, wi) = D(h) G1(wo) G1(wi) F / (4 wo.z wi.z) with h = normalize(wo + wi) and
// Schlick's F = specular_color + (1 - specular_color) (1 - dot(wi, h))^5 (per channel); 0 (all
// channels) unless wo.z > 0 and wi.z > 0. Your two functions above give D and G1 (when one of
// them is wrong, the hints say so here too). Handout section 4.
glm::vec3 microfacet_f(const glm::vec3& wo, const glm::vec3& wi, float alpha, const glm::vec3& specular_color) {
  (void)wo;
  (void)wi;
  (void)alpha;
  (void)specular_color;
  throw NotImplemented("microfacet_f");
}

// RETURN a unit half vector with z > 0 whose density (per steradian) is D(h) cos(theta_h): the
// inversion method of stage 07 on GGX (handout section 5 derives tan^2(theta_h) from one number
// and phi from the other).
glm::vec3 sample_ggx_half_vector(glm::vec2 uniform_random, float alpha) {
  (void)uniform_random;
  (void)alpha;
  // Delete the line below when you write the function (handout section 5).
  throw NotImplemented("sample_ggx_half_vector");
}

// RETURN the density of sample_ggx_half_vector's half vectors at `half_vector` (unit, local
// frame), per steradian: D(h) cos(theta_h); 0 when half_vector.z <= 0.
float ggx_half_vector_pdf(const glm::vec3& half_vector, float alpha) {
  (void)half_vector;
  (void)alpha;
  throw NotImplemented("ggx_half_vector_pdf");
}

// RETURN wi = 2 dot(wo, h) h - wo, wo mirrored about a half vector h from
// sample_ggx_half_vector(uniform_random, alpha). wo.z > 0. Return wi even when it is below the
// surface: the framework then has no sample. Handout section 6.
glm::vec3 sample_microfacet_wi(const glm::vec3& wo, glm::vec2 uniform_random, float alpha) {
  (void)wo;
  (void)uniform_random;
  (void)alpha;
  throw NotImplemented("sample_microfacet_wi");
}

// RETURN the density (per steradian) with which sample_microfacet_wi gives wi:
// ggx_half_vector_pdf(h, alpha) / (4 |dot(wo, h)|), h = normalize(wo + wi); 0 unless wo.z > 0
// and wi.z > 0. Handout section 6 shows where the 4 comes from.
float microfacet_pdf(const glm::vec3& wo, const glm::vec3& wi, float alpha) {
  (void)wo;
  (void)wi;
  (void)alpha;
  throw NotImplemented("microfacet_pdf");
}

}  // namespace raylab
