// Stage 10_microfacet (bonus): a rough metal, the GGX (Trowbridge-Reitz) microfacet BSDF with
// the Smith masking term and Schlick's Fresnel, and its importance sampling. Write the functions
// in assignments/10_microfacet/microfacet.cpp (its comments are the full contract); handout:
// docs/10_microfacet.md. The framework's BSDF of a "microfacet" material (raylab/bsdf.h) calls
// microfacet_f, sample_microfacet_wi and microfacet_pdf, so your stage 09 path tracer (and 09b's
// MIS) renders rough metals with them.
//
// Conventions (as stage 07): unit directions in a LOCAL frame whose z axis is the surface normal,
// so z = cos(theta); wo (towards the viewer) and wi (towards the light) both point AWAY from the
// surface; the half vector h = normalize(wo + wi). `alpha` is GGX's roughness parameter itself,
// in (0, 1] (not a "roughness" to be squared first): small is shiny, 1 is very rough. Densities
// of directions are per steradian.
#pragma once

#include <glm/glm.hpp>

namespace raylab {

// GGX's distribution of microfacet normals: D(h) = alpha^2 / (pi ((alpha^2 - 1) cos^2 + 1)^2)
// with cos = h.z, for h above the surface (0 for h.z <= 0). Normalised so that the integral of
// D(h) cos(theta_h) over the hemisphere is 1.
float ggx_distribution(const glm::vec3& half_vector, float alpha);

// Smith's masking of GGX: the fraction of the microfacets facing `direction` that it sees,
// G1(v) = 2 / (1 + sqrt(1 + alpha^2 tan^2(theta_v))); 1 along the normal, 0 for v.z <= 0.
float ggx_smith_g1(const glm::vec3& direction, float alpha);

// The BSDF of a rough metal whose reflectance at normal incidence is `specular_color`:
//   f(wo, wi) = D(h) G1(wo) G1(wi) F(wi . h) / (4 cos(theta_o) cos(theta_i)),
// F by Schlick: F(c) = specular_color + (1 - specular_color) (1 - c)^5. 0 unless wo and wi are
// both above the surface.
glm::vec3 microfacet_f(const glm::vec3& wo, const glm::vec3& wi, float alpha, const glm::vec3& specular_color);

// A half vector of the hemisphere z > 0 with density D(h) cos(theta_h) (per steradian), from two
// independent uniform numbers in [0, 1); ggx_half_vector_pdf gives that density (0 for h.z <= 0).
glm::vec3 sample_ggx_half_vector(glm::vec2 uniform_random, float alpha);
float ggx_half_vector_pdf(const glm::vec3& half_vector, float alpha);

// A direction wi for wo (wo.z > 0): a half vector h sampled as above, and wo mirrored about it,
// wi = 2 (wo . h) h - wo. wi may be below the surface (the caller then has no sample).
// microfacet_pdf gives wi's density, ggx_half_vector_pdf(h) / (4 |wo . h|); 0 unless wo and wi
// are both above the surface.
glm::vec3 sample_microfacet_wi(const glm::vec3& wo, glm::vec2 uniform_random, float alpha);
float microfacet_pdf(const glm::vec3& wo, const glm::vec3& wi, float alpha);

}  // namespace raylab
