// Stage 09_path: the path tracer (GAMES101 assignment 7).          Handout: docs/09_path.md
//
// A camera ray hits a surface; the light leaving that surface towards the camera is its own
// emission plus the light it reflects, which arrives from every direction: from the lights
// directly, and from other surfaces, which reflect light in turn (the rendering equation,
// handout section 1). A path tracer estimates it with one random path per sample: at each
// surface, the direct light (stage 08), then one new direction sampled from the BSDF, and on.
//
// WHAT YOU GET
//   context.geometry.intersect(ray)   the closest hit (SurfaceHit: point, geometric_normal,
//                                     material) or nullopt; context.scene.background where none
//   context.scene.materials[hit->material]   its material; emitted_radiance(material, *hit,
//                                     ray.direction) its emission towards the ray (raylab/shading.h)
//   bsdf_of(material, diffuse_color_at(material, *hit))   its BSDF (raylab/bsdf.h):
//                                     is_specular() for mirrors and glass; bsdf_sample_f(...)
//                                     samples a new direction wi with f and pdf (nullopt: stop)
//   estimate_direct_light(context, *hit, bsdf, wo, sampler)   stage 08, for diffuse surfaces
//   spawn_ray(*hit, wi)               the next ray, starting just off the surface
//   context.max_depth                 the most bounces after the camera ray (--max-depth): the
//                                     surfaces at depth 0, 1, ..., max_depth all count (emission
//                                     and direct light); the path stops after the one at
//                                     depth == max_depth (it needs no next direction)
//   context.continue_probability(depth, throughput)   p in (0, 1]: the chance to go on after
//                                     this surface. depth: bounces so far (0 at the camera ray's
//                                     hit); throughput: the weight that reached this surface,
//                                     before you sample the next direction. --roulette sets it:
//                                     a fixed P (1: no roulette) or auto (by the throughput);
//                                     the arguments change the noise, never the mean
//   sampler.get_1d(), sampler.get_2d()   your random numbers (uniform in [0, 1)), the only ones
//                                     (no rand(): the same seed must give the same picture)
//
// THE RULES (handout sections 2-5)
//   - Weigh each bounce by f * |cos(theta_i)| / pdf (cos against the geometric normal).
//   - Russian roulette: go on with probability p, and when you do, divide by p.
//   - Emission counts once: when the camera sees a light, and after a mirror or glass bounce;
//     never after a diffuse bounce, whose light estimate_direct_light counted already.
//   - Mirrors and glass need no direct light: their f is 0 for every sampled light direction,
//     so estimate_direct_light would add 0 there (skip it, it saves a shadow ray).
//
// READ docs/09_path.md, section 6 for the common mistakes (the autograder's hints name them).
//
// HOW TO CHECK
//   build/bin/autograder --stage 09_path
//   build/bin/raylab render scenes/furnace.json -o furnace.exr --integrator path --spp 16
//     (every pixel should be 2: the enclosure's emission 1 over 1 - albedo 0.5)
//   build/bin/raylab render scenes/cornell.json -o cornell.png --integrator path --spp 64
#include "raylab/bsdf.h"
#include "raylab/error.h"
#include "raylab/shading.h"
#include "raylab/stages/08_direct_light.h"
#include "raylab/stages/09_path.h"

namespace raylab {

// RETURN the radiance arriving at the camera along `camera_ray` (one random path's estimate).
glm::vec3 path_radiance(const RenderContext& context, const Ray& camera_ray, Sampler& sampler) {
  (void)context;
  (void)camera_ray;
  (void)sampler;
  // Delete the line below when you write the function (handout sections 2-5).
  throw NotImplemented("path_radiance");
}

}  // namespace raylab
