// The traversal that several stage-05 self-test submissions share: the course's stack
// traversal (the near child entered first, the far one pushed, t_max lowered after each hit,
// one loop for closest and any hit), with each submission's mistake as a flag. Without flags
// it is correct; each flag is one mistake a student makes, and its self-test checks the
// grader's verdict and hint for it (tests/submissions/CMakeLists.txt).
#pragma once

#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"

#include <cstdint>
#include <limits>
#include <optional>

namespace raylab::submission {

struct TraversalMistakes {
  bool far_child_first = false;             // enters the far child and pushes the near one
  bool leaf_position_as_primitive = false;  // tests primitive i (the leaf position), not primitive_order[i]
  bool t_max_not_lowered = false;           // keeps the closest hit by comparison; search.t_max stays
  bool prunes_only_at_leaves = false;       // tests every node's box but enters every inner node anyway
  bool primitives_not_counted = false;      // leaves stats.primitives_tested as it was
  bool any_hit_at_leaf_box = false;         // any_hit: stops at the first leaf whose box the ray hits and
                                            // returns its first primitive, hit or not
  bool any_hit_goes_on = false;             // any_hit: searches on for the closest hit (right answers, more work)
  bool ignores_ray_interval = false;        // searches [0, infinity), not the incoming ray's [t_min, t_max]
  bool returns_leaf_position = false;       // tests primitive_order[i] but returns i, its position in the leaf
  bool empty_tree_not_checked = false;      // reads nodes[0] of a tree without nodes
};

// What the traversal writes into stats.nodes_visited.
enum class NodesReport {
  Honest,       // every node box tested (the contract)
  One,          // 1 per ray: a lie below what the grader knows was visited
  LowerBound,   // the nodes on the paths from the root to the leaves whose primitives were tested:
                // a lie exactly at the lower bound the grader can check
};

inline std::optional<BvhHit> traverse_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                          bool any_hit, BvhTraversalStats& stats, TraversalMistakes mistakes,
                                          NodesReport report = NodesReport::Honest) {
  if (bvh.nodes.empty() && !mistakes.empty_tree_not_checked) return std::nullopt;
  const glm::vec3 ray_direction_inverse = ray_direction_inverse_of(ray);
  // 1 / -0 = -infinity < 0: a -0 component counts as negative, consistently with the box test.
  const bool direction_negative[3] = {ray_direction_inverse.x < 0.0f,
                                      ray_direction_inverse.y < 0.0f,
                                      ray_direction_inverse.z < 0.0f};
  const BvhNode* nodes = bvh.nodes.data();
  const std::uint32_t* primitive_order = bvh.primitive_order.data();

  Ray search = ray;
  if (mistakes.ignores_ray_interval) {
    search.t_min = 0.0f;
    search.t_max = std::numeric_limits<float>::infinity();
  }
  std::optional<BvhHit> closest;
  // With prunes_only_at_leaves the stack holds every pending sibling of a root path: its depth
  // bounds it, so kBvhMaxDepth entries suffice either way.
  std::uint32_t stack[kBvhMaxDepth], stack_depth[kBvhMaxDepth];
  int stack_size = 0;
  std::uint32_t node_index = 0, depth = 0;
  std::uint64_t nodes_visited = 0, primitives_tested = 0;  // locals: kept in registers
  // NodesReport::LowerBound: the current root path's nodes, counted once each when a leaf below
  // them has its primitives tested (a depth-first traversal keeps the path above a popped node).
  bool path_counted[kBvhMaxDepth + 1] = {};
  std::uint64_t path_nodes = 0;

  for (;;) {
    const BvhNode& node = nodes[node_index];
    ++nodes_visited;
    path_counted[depth] = false;
    const std::optional<float> box_t = intersect_ray_box(search, ray_direction_inverse, node.bounds);
    const bool box_hit = box_t.has_value();
    if (box_hit && any_hit && mistakes.any_hit_at_leaf_box && node.is_leaf()) {
      closest = BvhHit{*box_t, primitive_order[node.first_index]};
      break;
    }
    if (box_hit || (mistakes.prunes_only_at_leaves && !node.is_leaf())) {
      if (!node.is_leaf()) {
        // The second child is the nearer one when the ray runs towards -split_axis.
        const bool enter_second = direction_negative[node.split_axis] != mistakes.far_child_first;
        stack_depth[stack_size] = depth + 1;
        stack[stack_size++] = node.first_index + (enter_second ? 0u : 1u);  // visited later
        node_index = node.first_index + (enter_second ? 1u : 0u);
        ++depth;
        continue;
      }
      for (std::uint32_t d = depth + 1; d-- > 0 && !path_counted[d];) {
        path_counted[d] = true;
        ++path_nodes;
      }
      const std::uint32_t leaf_end = node.first_index + node.primitive_count;
      for (std::uint32_t i = node.first_index; i < leaf_end; ++i) {
        const std::uint32_t primitive = mistakes.leaf_position_as_primitive ? i : primitive_order[i];
        ++primitives_tested;
        if (const std::optional<float> t = intersector.test(intersector.context, search, primitive)) {
          if (mistakes.t_max_not_lowered) {
            if (!closest || *t < closest->t_hit) closest = BvhHit{*t, primitive};
          } else {
            search.t_max = *t;
            closest = BvhHit{*t, mistakes.returns_leaf_position ? i : primitive};
          }
          if (any_hit && !mistakes.any_hit_goes_on) {
            stack_size = 0;  // done: fall through to the exit below
            break;
          }
        }
      }
      if (any_hit && closest && !mistakes.any_hit_goes_on) break;
    }
    if (stack_size == 0) break;
    --stack_size;
    node_index = stack[stack_size];
    depth = stack_depth[stack_size];
  }
  stats.nodes_visited += report == NodesReport::Honest ? nodes_visited : report == NodesReport::One ? 1 : path_nodes;
  if (!mistakes.primitives_not_counted) stats.primitives_tested += primitives_tested;
  return closest;
}

}  // namespace raylab::submission
