// What the suites call in stage code besides the stage functions themselves. Each has two
// definitions: local_stage_calls.cpp (the stage server and the regenerate tool, which link stage
// code) and remote_stages.cpp (the judge, which sends one request to the stage server).
#pragma once

#include "protocol.h"

#include "raylab/geometry.h"
#include "raylab/image.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/testkit/triangles.h"
#include "raylab/testkit/warps.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab::grading {

using testkit::TriangleFunction;  // intersect_ray_triangle or intersect_ray_triangle_watertight

// For each ray i, the triangles (indices into `triangles`) among candidates[i] that
// function(ray, p0, p1, p2) reports a hit for; every triangle is a candidate when `candidates` is
// empty. function is intersect_ray_triangle or intersect_ray_triangle_watertight.
std::vector<std::vector<std::uint32_t>> triangles_hit(TriangleFunction function,
                                                      const std::vector<protocol::Triangle>& triangles,
                                                      const std::vector<Ray>& rays,
                                                      const std::vector<std::vector<std::uint32_t>>& candidates);

// The picture a stage's image test renders (stages.json: "image"), the same for the student
// and the reference, kImageWidth x kImageHeight (support.h). What it shows:
//   ray_directions  camera-ray directions as colours (only stage 1's function runs)
//   spheres         the scene's spheres, its meshes left out
//   everything      the whole scene, through whatever stages the renderer uses
Image render_stage_image(const std::string& stage_id);

// Stage 07's warps, each with its density, called in bulk (a chi-square test needs 10^5 samples).
using testkit::kWarps;
using testkit::Warp;
using testkit::warp_pdf_function;
using testkit::warp_sample_function;

// The warp's result for each input: a direction as is; a disk point (x, y) as (x, y, 0);
// barycentrics as (barycentric_b1, barycentric_b2, 0).
std::vector<glm::vec3> warp_samples(Warp warp, const std::vector<glm::vec2>& uniform_randoms);
// The warp's density at each argument: a direction; a disk point (x, y, ignored); for the
// triangle, three consecutive vec3 are one call's corners (p0, p1, p2).
std::vector<float> warp_pdfs(Warp warp, const std::vector<glm::vec3>& arguments);

// Stage 08: a test scene for estimate_direct_light, built in the stage server. Every triangle
// and sphere emits its radiance from its front (a triangle's by winding); a triangle of zero
// emission is an occluder (black). Plain values only: the judge sends them as they are.
struct DirectLightTriangle {
  glm::vec3 p0{0.0f}, p1{0.0f}, p2{0.0f};
  glm::vec3 emission{0.0f};
};
struct DirectLightSphere {
  glm::vec3 center{0.0f};
  float radius = 1.0f;
  glm::vec3 emission{0.0f};
};
struct DirectLightPoint {
  glm::vec3 position{0.0f};
  glm::vec3 intensity{0.0f};
};
struct DirectLightScene {
  std::vector<DirectLightTriangle> triangles;
  std::vector<DirectLightSphere> spheres;
  std::vector<DirectLightPoint> point_lights;
};
// A diffuse surface point that is not part of the scene: where, its unit normal, the unit
// direction towards the viewer, its albedo, and how many independent samples to take there.
struct DirectLightQuery {
  glm::vec3 point{0.0f}, normal{0.0f, 0.0f, 1.0f}, wo{0.0f, 0.0f, 1.0f}, albedo{0.5f};
  std::uint32_t sample_count = 1;
};
// estimate_direct_light's samples, query after query (sample_count of each), each drawn with a
// fresh 1-spp sampler of `seed` (independent numbers).
std::vector<glm::vec3> direct_light_samples(const DirectLightScene& scene, const std::vector<DirectLightQuery>& queries,
                                            std::uint64_t seed);

// Stage 09: a scene file of the kit rendered with the path integrator (path_radiance), with
// changes for the test: each pixel's mean and its variance of the mean (film.h).
struct PathRenderRequest {
  int width = 32, height = 32, samples_per_pixel = 4, max_depth = 5;
  float roulette_probability = 1.0f;
  float albedo = -1.0f;  // >= 0: every material's diffuse colour becomes this grey (furnaces)
  std::uint64_t seed = 0;
  // 1: no picture, one path_radiance call along the camera's view direction (the stage's probe:
  // it reaches path_radiance before any other stage's function), returned as a 1x1 picture.
  int probe_only = 0;
};
struct PathRenderResult {
  Image mean, variance_of_mean;
};
PathRenderResult path_render(const std::string& scene_path, const PathRenderRequest& request);

// The grader's own triangle test (Cramer's rule in double), as a PrimitiveIntersector test over
// `triangles` (a const std::vector<protocol::Triangle>*), so that BVH grades do not depend on
// your stage 3.
std::optional<float> grader_triangle_test(void* triangles, const Ray& ray, std::uint32_t primitive);

// The grader's own camera rays, sphere and triangle tests (in double, with stages 01-03's
// conventions), which stages 08 and 09 trace their scenes with: so their grades do not depend on
// your stages 01-05, only on the stages they build on (stages.json: "needs").
TracingFunctions grader_tracing();

}  // namespace raylab::grading
