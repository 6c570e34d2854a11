// Stage 05c_wide_bvh (bonus): a 4-wide BVH. Collapse your binary tree into one whose nodes hold
// up to four children, test a ray against all four children's boxes at once (SIMD), and find
// the closest (or any) hit through it. Write it in assignments/05c_wide_bvh/wide_bvh.cpp (its
// comment is the full contract); handout: docs/05c_wide_bvh.md.
#pragma once

#include "raylab/ray.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace raylab {

constexpr int kBvh4Width = 4;  // children per node

// One node of a 4-wide BVH, 128 bytes (two cache lines). The boxes of its children sit side by
// side, one coordinate per array ("structure of arrays"), so that one SIMD instruction handles a
// coordinate of all four boxes: child i's box is [min_x[i], max_x[i]] x [min_y[i], max_y[i]] x
// [min_z[i], max_z[i]].
//   slot i < child_count, primitive_count[i] == 0: an inner child, the node nodes[child[i]];
//   slot i < child_count, primitive_count[i] > 0:  a leaf, the primitives
//                                                  primitive_order[child[i]] ... [child[i] + primitive_count[i] - 1];
//   slot i >= child_count: empty; its box is empty (every min +infinity, every max -infinity),
//                          child[i] and primitive_count[i] are 0.
struct alignas(64) Bvh4Node {
  float min_x[kBvh4Width], min_y[kBvh4Width], min_z[kBvh4Width];
  float max_x[kBvh4Width], max_y[kBvh4Width], max_z[kBvh4Width];
  std::uint32_t child[kBvh4Width];
  std::uint16_t primitive_count[kBvh4Width];
  std::uint8_t child_count = 0;  // 1 .. 4 (1 only for a root whose tree is one leaf)
  std::uint8_t padding[7] = {};

  bool is_leaf(int slot) const { return primitive_count[slot] > 0; }
  Bounds3 child_bounds(int slot) const {
    return {{min_x[slot], min_y[slot], min_z[slot]}, {max_x[slot], max_y[slot], max_z[slot]}};
  }
};
static_assert(sizeof(Bvh4Node) == 128, "a Bvh4Node must stay 128 bytes (two cache lines)");

// A 4-wide tree. nodes[0] is the root; both vectors are empty when there are no primitives.
// (std::vector allocates alignas(64) types on 64-byte boundaries: every node starts a cache line.)
struct Bvh4 {
  std::vector<Bvh4Node> nodes;
  std::vector<std::uint32_t> primitive_order;  // the binary tree's, unchanged
};

// A Bvh4Node with every slot empty (child_count 0, empty boxes): where a collapse starts.
Bvh4Node empty_bvh4_node();

// The 4-wide tree of a binary tree (stage 05's Bvh, built by build_bvh or build_bvh_sah): the
// same leaves (the same primitive ranges, with the binary leaves' boxes), each inner node of up
// to four children, made by pulling grandchildren up into their grandparent. A binary tree of
// n inner nodes gives at most 3 n / 4 + 1 wide nodes (about n / 3 where every wide node has four
// children; n for a tree not collapsed at all).
Bvh4 collapse_bvh4(const Bvh& binary);

// Stage 04's box test on the four children of `node` at once. Returns a bit mask: bit i set
// when slot i < child_count and the ray's points with t in [ray.t_min, ray.t_max] meet child i's
// closed box; then entry_distances[i] = max(entry distance, ray.t_min), as intersect_ray_box
// returns (the other entries are left unspecified). Never loses a hit (stage 04's rules for zero
// direction components and rounding hold for each child).
unsigned intersect_ray_box4(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bvh4Node& node,
                            float entry_distances[kBvh4Width]);

// Stage 05's intersect_bvh through a 4-wide tree: the same contract and the same answers (the
// closest hit, or any hit), with stats.nodes_visited counting the Bvh4 nodes whose four boxes
// were tested (one intersect_ray_box4 each) and stats.primitives_tested every call of
// intersector.test.
std::optional<BvhHit> intersect_bvh4(const Bvh4& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                     bool any_hit, BvhTraversalStats& stats);

}  // namespace raylab
