// Stage 05_bvh: a bounding volume hierarchy -- build it (median split; 5b: binned SAH) and
// find the closest (or any) hit through it. Write it in assignments/05_bvh/bvh.cpp (its
// comment is the full contract); handout: docs/05_bvh.md.
//
// The node layout and the containers below are the framework's: the builders fill them, the
// traversal reads them, the renderer, the autograder and bench/ inspect them (with the tools
// of raylab/bvh_tools.h: SAH cost, depth, the invariant check, printing a node).
#pragma once

#include "raylab/bounds.h"
#include "raylab/bvh_node_allocator.h"
#include "raylab/ray.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace raylab {

// One node, 32 bytes, so that two share a 64-byte cache line. All nodes of a tree live in
// one array (Bvh::nodes); nodes[0] is the root.
//   inner node: primitive_count == 0; its two children are nodes[first_index] and
//               nodes[first_index + 1] (siblings are adjacent). The first child holds the
//               primitives with the SMALLER centroids along split_axis.
//   leaf:       primitive_count > 0; its primitives are primitive_order[first_index] ..
//               primitive_order[first_index + primitive_count - 1].
struct BvhNode {
  Bounds3 bounds;                     // holds every primitive below this node
  std::uint32_t first_index = 0;      // first child (inner) or first primitive (leaf)
  std::uint16_t primitive_count = 0;  // 0 for an inner node
  std::uint8_t split_axis = 0;        // inner: 0 = x, 1 = y, 2 = z; lets traversal enter the near child first
  std::uint8_t padding = 0;

  bool is_leaf() const { return primitive_count > 0; }
};
static_assert(sizeof(BvhNode) == 32, "a BvhNode must stay 32 bytes (two per cache line)");

// The largest leaf a builder may make (primitive_count is 16 bits).
constexpr int kBvhMaxLeafSize = 65535;
// Builders never make a tree deeper than this (the root has depth 0), so a traversal stack of
// kBvhMaxDepth node indices is always enough.
constexpr int kBvhMaxDepth = 64;

// A built tree. The primitives themselves stay with the caller, who knows only their boxes'
// order: primitive i is the one whose box was primitive_bounds[i].
struct Bvh {
  std::vector<BvhNode, BvhNodeAllocator<BvhNode>> nodes;  // empty when there are no primitives
  std::vector<std::uint32_t> primitive_order;  // a permutation of 0 .. primitive count - 1
};

// A BVH over primitive_bounds (one box per primitive, in the caller's order) by the median
// split: split the node's longest axis at the median primitive centroid, stop at leaves of
// at most max_leaf_size primitives (1 .. kBvhMaxLeafSize; std::invalid_argument otherwise).
Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size);

// Stage 5b (bonus): the same, choosing each split with the binned surface area heuristic;
// leaves have at most max_leaf_size primitives and are made earlier when splitting costs more
// (traversal step cost 1, primitive test cost 1: see bvh_sah_cost in raylab/bvh_tools.h).
Bvh build_bvh_sah(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size);

// ---- Traversal --------------------------------------------------------------------------

// How the traversal tests one primitive: a plain function pointer and the caller's context.
//
// Why this shape: the traversal is a stage function, compiled in a separate library from the
// framework that owns the primitives (triangles, spheres, or whole meshes), so it cannot be a
// template over the test. A std::function may allocate and adds a second indirection; a
// virtual interface costs a vtable load per call. A function pointer + void* is one
// predictable indirect call per primitive, allocates nothing, and lets the framework count
// every test and keep the details of the best hit (barycentrics, ...) in its context.
//
// test(context, ray, primitive) returns the primitive's hit distance t if it is hit with
// ray.t_min < t < ray.t_max, else std::nullopt. `primitive` is the caller's own index (a
// value of Bvh::primitive_order). The traversal may call it in any order: the caller keeps
// the details of the closest hit by its own comparison of t, and uses the BvhHit the
// traversal returns (if that names another primitive, the caller recomputes its details).
// A good traversal passes a ray whose t_max is the closest hit found so far, so that farther
// primitives are not tested at all (the autograder counts this work).
struct PrimitiveIntersector {
  using TestFunction = std::optional<float> (*)(void* context, const Ray& ray, std::uint32_t primitive);
  TestFunction test = nullptr;
  void* context = nullptr;
};

// The work one query did, counted the same way by every correct traversal (bench/, grader).
struct BvhTraversalStats {
  std::uint64_t nodes_visited = 0;      // node boxes tested against the ray
  std::uint64_t primitives_tested = 0;  // calls of intersector.test
};

struct BvhHit {
  float t_hit = 0.0f;
  std::uint32_t primitive = 0;  // the caller's index, as passed to intersector.test
};

// closest hit (any_hit == false): the hit with the smallest t in (ray.t_min, ray.t_max);
// any hit (any_hit == true, shadow rays): the first hit found, stopping at once.
// std::nullopt when nothing is hit. Adds the work done to `stats` (it does not reset it).
std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray,
                                    const PrimitiveIntersector& intersector, bool any_hit,
                                    BvhTraversalStats& stats);

}  // namespace raylab
