// Stage 07's batch calls (07_sampling_calls.cpp): each warp and its density, called in bulk (a
// chi-square test needs 10^5 samples).
#pragma once

#include "raylab/testkit/warps.h"

#include <glm/glm.hpp>

#include <vector>

namespace raylab::grading {

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

}  // namespace raylab::grading
