// Stage 09_path: the path tracer. Write path_radiance in assignments/09_path/path.cpp (its
// comments are the full contract); handout: docs/09_path.md. `raylab render ... --integrator
// path` renders with it (--max-depth sets context.max_depth, --roulette
// context.continue_probability).
#pragma once

#include "raylab/integrator.h"
#include "raylab/ray.h"
#include "raylab/sampler.h"

#include <glm/glm.hpp>

namespace raylab {

// The radiance (linear RGB) arriving at the camera along `camera_ray`: emission seen directly
// or after mirrors and glass, direct light (stage 08's estimate_direct_light) at every diffuse
// surface, and the light of further bounces sampled from the BSDF, with Russian roulette.
// Random numbers from `sampler` only. Its expected value is the rendering equation's answer.
glm::vec3 path_radiance(const RenderContext& context, const Ray& camera_ray, Sampler& sampler);

}  // namespace raylab
