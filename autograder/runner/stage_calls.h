// What the suites call in stage code besides the stage functions themselves. Each has two
// definitions: local_stage_calls.cpp (the stage server and the regenerate tool, which link stage
// code) and remote_stages.cpp (the judge, which sends one request to the stage server).
#pragma once

#include "protocol.h"

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

// The grader's own triangle test (Cramer's rule in double), as a PrimitiveIntersector test over
// `triangles` (a const std::vector<protocol::Triangle>*), so that BVH grades do not depend on
// your stage 3.
std::optional<float> grader_triangle_test(void* triangles, const Ray& ray, std::uint32_t primitive);

}  // namespace raylab::grading
