// Stage 05d_kdtree (bonus): a KD-tree. Cut space (not the primitives) into cells by planes chosen
// with the surface area heuristic, list in each leaf cell every primitive whose box reaches into it
// (a primitive may be in several leaves), and find the closest (or any) hit by walking the cells
// the ray crosses, front to back. Write it in assignments/05d_kdtree/kdtree.cpp (its comment is
// the full contract); handout: docs/05d_kdtree.md.
//
// The primitives are known by their boxes only, as in stage 05_bvh; the traversal tests them
// through the same PrimitiveIntersector and reports the same BvhHit and BvhTraversalStats.
#pragma once

#include "raylab/bounds.h"
#include "raylab/ray.h"
#include "raylab/stages/05_bvh.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace raylab {

// One node, 16 bytes. All nodes of a tree live in one array (KdTree::nodes); nodes[0] is the root,
// whose cell is KdTree::bounds. A node's cell is its parent's, cut by the parent's plane.
//   inner node: leaf == 0; the plane {p : p[split_axis] == split_position} cuts the node's
//               cell in two: nodes[first_index] is the part below the plane (p[split_axis] <=
//               split_position), nodes[first_index + 1] the part above it (siblings are adjacent).
//   leaf:       leaf == 1; its primitives are primitive_indices[first_index] ..
//               primitive_indices[first_index + primitive_count - 1]. primitive_count may be 0:
//               an empty cell, which a ray crosses without a test.
struct KdNode {
  float split_position = 0.0f;        // inner: where the plane cuts split_axis
  std::uint32_t first_index = 0;      // first child (inner) or first entry of primitive_indices (leaf)
  std::uint32_t primitive_count = 0;  // leaf: how many primitives it lists; 0 for an inner node
  std::uint8_t split_axis = 0;        // inner: 0 = x, 1 = y, 2 = z
  std::uint8_t leaf = 0;               // 1: a leaf, 0: an inner node
  std::uint8_t padding[2] = {};

  bool is_leaf() const { return leaf != 0; }
};
static_assert(sizeof(KdNode) == 16, "a KdNode must stay 16 bytes (four per cache line)");

// Builders never make a tree deeper than this (the root has depth 0), so a traversal stack of
// kKdMaxDepth cells is always enough; nor one of more than 16 n + 1 nodes over n primitives (a
// tree built by the SAH has a few per primitive).
constexpr int kKdMaxDepth = 64;

// A built tree. The primitives stay with the caller, who knows only their boxes' order: primitive i
// is the one whose box was primitive_bounds[i].
struct KdTree {
  Bounds3 bounds;                                // the root's cell: the union of every primitive's box
  std::vector<KdNode> nodes;                     // empty when there are no primitives
  std::vector<std::uint32_t> primitive_indices;  // the leaves' lists, one after another
};

// The costs of the surface area heuristic for a KD-tree: a step into a node costs 1, a primitive
// test 1 (as stage 05b's), and a split with an empty side earns a bonus: its cost is
//   1 + (1 - kKdEmptyBonus) * (A(below) / A(cell) * n_below + A(above) / A(cell) * n_above)
// (A: surface area; the bonus only when n_below or n_above is 0), against n for a leaf of n.
constexpr float kKdEmptyBonus = 0.5f;

// The deepest a tree over n primitives may go: 8 + 1.3 log2(n), rounded down, and at most
// kKdMaxDepth (pbrt's rule: deeper trees cost more memory than they save in tests).
inline int kdtree_max_depth(std::size_t primitive_count) {
  if (primitive_count < 2) return 8;
  const int depth = static_cast<int>(8.0 + 1.3 * std::log2(static_cast<double>(primitive_count)));
  return depth < kKdMaxDepth ? depth : kKdMaxDepth;
}

// A KD-tree over primitive_bounds (one box per primitive, in the caller's order), each split the
// cheapest plane by the cost above, among planes at the primitives' box faces strictly inside the
// cell (or at evenly spaced bins: a different, coarser choice is fine). A node becomes a leaf when
// no split costs less than making it one, or at kdtree_max_depth. A primitive goes below a plane
// when its box reaches below it (min < split_position), above when its box reaches above it
// (max > split_position), so to both sides when it crosses it; one whose box lies in the plane
// goes to one side.
KdTree build_kdtree(const std::vector<Bounds3>& primitive_bounds);

// Stage 05's intersect_bvh through a KD-tree: the same contract and the same answers (the closest
// hit in (ray.t_min, ray.t_max), or with any_hit the first hit found), walking the cells the ray
// crosses front to back. The closest hit so far counts only once the walk has left no nearer
// cell: a hit beyond the cell being walked may be beaten in the next one. stats.nodes_visited
// counts the nodes the walk steps into (inner nodes and leaves), stats.primitives_tested every
// call of intersector.test (a primitive in two leaves may be tested twice).
std::optional<BvhHit> intersect_kdtree(const KdTree& tree, const Ray& ray, const PrimitiveIntersector& intersector,
                                       bool any_hit, BvhTraversalStats& stats);

}  // namespace raylab
