// Stage 04's calls between the judge and the stage server (04_box_calls.cpp) that other stages'
// tests use: the box test on many inputs at once.
#pragma once

#include "raylab/bounds.h"
#include "raylab/ray.h"

#include <optional>
#include <tuple>
#include <vector>

namespace raylab::grading {

// intersect_ray_box(ray, ray_direction_inverse, box) on each set of arguments, in order; in the
// judge, all of them in one request (stage_call.h, call_remote_each).
using BoxTestArguments = std::tuple<Ray, glm::vec3, Bounds3>;
std::vector<std::optional<float>> intersect_ray_box_each(const std::vector<BoxTestArguments>& calls);

}  // namespace raylab::grading
