// Stage 05d's batch call (05d_kdtree_calls.cpp): intersect_kdtree on many rays at once with the
// grader's triangle test; build_kdtree and one intersect_kdtree are one call each.
#pragma once

#include "protocol.h"

#include "raylab/stages/05d_kdtree.h"

#include <optional>
#include <vector>

namespace raylab::grading {

// intersect_kdtree(tree, ray, the grader's triangle test on `triangles`, any_hit, stats) on each
// ray, in order: the hits, in one request (the tree and the mesh are sent only when the stage
// server does not hold them already).
std::vector<std::optional<BvhHit>> intersect_kdtree_each(const KdTree& tree,
                                                         const std::vector<protocol::Triangle>& triangles,
                                                         const std::vector<Ray>& rays, bool any_hit);

}  // namespace raylab::grading
