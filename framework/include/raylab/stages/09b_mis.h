// Stage 09b_mis (bonus): multiple importance sampling (MIS) of the lights and the BSDF, with the
// power heuristic. Write the functions in assignments/09b_mis/mis.cpp (its comments are the full
// contract); handout: docs/09b_mis.md. `raylab render ... --integrator mis` renders with
// path_radiance_mis (--max-depth and --roulette as for stage 09's path tracer).
#pragma once

#include "raylab/integrator.h"
#include "raylab/ray.h"
#include "raylab/sampler.h"

#include <glm/glm.hpp>

namespace raylab {

// The power heuristic's weight (exponent 2) of a sample made by strategy f, which takes
// `count_f` samples with density `pdf_f`, against strategy g (`count_g` samples of density
// `pdf_g`) that could have made the same sample: (count_f pdf_f)^2 / ((count_f pdf_f)^2 +
// (count_g pdf_g)^2). Densities in the same measure (per steradian); an infinite pdf_f (a delta,
// which only f can sample) gives 1, a pdf_f of 0 gives 0, never NaN.
float power_heuristic(int count_f, float pdf_f, int count_g, float pdf_g);

// stage 09's path_radiance with MIS: at every diffuse surface one light sample and the BSDF
// sample that continues the path both count the light they find, each weighted by the power
// heuristic against the other strategy, so that their weights add up to 1 for every path. The
// same expected value as path_radiance; random numbers from `sampler` only.
glm::vec3 path_radiance_mis(const RenderContext& context, const Ray& camera_ray, Sampler& sampler);

}  // namespace raylab
