// Stage 09b_mis (bonus): multiple importance sampling (MIS).        Handout: docs/09b_mis.md
//
// Your stage 09 path tracer finds the light in two ways: a light sample (stage 08: a point
// chosen on a light) and, after a mirror or glass, the BSDF sample that happens to hit a light.
// Light sampling is good for small lights, BSDF sampling for big lights and shiny surfaces. MIS
// lets BOTH strategies count the light they find at every diffuse surface, each weighted so that
// the weights of the two add up to 1 for every path (handout sections 1-3): the noise of the
// better strategy, wherever that is, and still the right answer.
//
// WHAT YOU GET (besides what stage 09 uses)
//   sample_li(light, hit.point, uv)       its .pdf is per steradian; .is_delta for a point light
//   context.lights.choose(u, &probability)   the light, and the probability of choosing it
//   context.lights.pdf_li(point, wi)      the light strategy's density (per steradian, the choice
//                                         probability included) of the unit direction wi from point
//   bsdf_pdf(bsdf, normal, wo, wi)        the BSDF strategy's density of wi (per steradian)
//   (raylab/lights.h, raylab/bsdf.h)
//
// THE RULES (handout section 3)
//   - Compare the two strategies' densities of the SAME direction, both per steradian: the light
//     strategy's is light_sample.pdf * choice probability (or context.lights.pdf_li), never
//     1 / area.
//   - A light sample gets power_heuristic(1, light's density, 1, BSDF's density); a BSDF sample that
//     hits a light after a DIFFUSE bounce gets power_heuristic(1, BSDF's density, 1, light's).
//   - Weight 1 where only one strategy can make the path: a point light (is_delta), the camera's
//     hit and the hit after a mirror or glass, and the light sample at the last vertex
//     (depth == context.max_depth: no BSDF sample follows it).
//   - Not graded, but right: draw the light's point with one sampler.get_2d() and the BSDF's
//     direction with another, so that the two choices are independent.
//
// READ docs/09b_mis.md, section 5 for the common mistakes (the autograder's hints name them).
//
// HOW TO CHECK
//   build/bin/autograder --stage 09b_mis
//   build/bin/raylab render scenes/cornell.json -o cornell_mis.png --integrator mis --spp 64
//     (the same picture as --integrator path: in this box, with a small light, about the same noise)
#include "raylab/bsdf.h"
#include "raylab/error.h"
#include "raylab/lights.h"
#include "raylab/shading.h"
#include "raylab/stages/09b_mis.h"

namespace raylab {

// RETURN the power heuristic's weight of a sample of strategy f against strategy g:
// (count_f pdf_f)^2 / ((count_f pdf_f)^2 + (count_g pdf_g)^2). An infinite pdf_f (a delta) gives
// 1; a pdf_f of 0 gives 0 (also when pdf_g is 0 too: never NaN). Handout section 2.
float power_heuristic(int count_f, float pdf_f, int count_g, float pdf_g) {
  (void)count_f;
  (void)pdf_f;
  (void)count_g;
  (void)pdf_g;
  // Delete the line below when you write the function (handout section 2).
  throw NotImplemented("power_heuristic");
}

// RETURN the radiance arriving at the camera along `camera_ray`, as stage 09's path_radiance, with
// the light sample and the BSDF sample of every diffuse surface weighted by power_heuristic.
// Start from a copy of your path_radiance; your light sample is your estimate_direct_light with
// its weight (handout section 4 goes through the changes one by one).
glm::vec3 path_radiance_mis(const RenderContext& context, const Ray& camera_ray, Sampler& sampler) {
  (void)context;
  (void)camera_ray;
  (void)sampler;
  throw NotImplemented("path_radiance_mis");
}

}  // namespace raylab
