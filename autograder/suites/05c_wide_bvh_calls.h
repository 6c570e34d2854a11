// Stage 05c's batch call (05c_wide_bvh_calls.cpp): intersect_ray_box4 on many (ray, node) pairs
// at once; collapse_bvh4 and intersect_bvh4 are one call each.
#pragma once

#include "raylab/stages/05c_wide_bvh.h"

#include <array>
#include <vector>

namespace raylab::grading {

struct Box4Answer {
  unsigned mask = 0;
  std::array<float, kBvh4Width> entry_distances{};
};

// intersect_ray_box4(rays[i], ray_direction_inverse_of(rays[i]), nodes[i], ...) for each i.
std::vector<Box4Answer> box4_answers(const std::vector<Ray>& rays, const std::vector<Bvh4Node>& nodes);

}  // namespace raylab::grading
