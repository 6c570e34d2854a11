// The framework's side of stages 04_box, 05_bvh and 05c_wide_bvh: printing, and measuring and checking a
// built tree (SAH cost, depth, invariants) for the renderer, bench/ and the autograder.
#include "raylab/bounds.h"
#include "raylab/bvh_tools.h"
#include "raylab/stages/05_bvh.h"
#include "raylab/stages/05c_wide_bvh.h"

#include <algorithm>
#include <limits>
#include <sstream>

namespace raylab {

std::ostream& operator<<(std::ostream& out, const Bounds3& box) {
  if (box.is_empty()) return out << "[empty]";
  return out << '[' << box.min << " .. " << box.max << ']';
}

std::ostream& operator<<(std::ostream& out, const BvhNode& node) {
  out << "node " << node.bounds;
  // In 64 bits: a broken node's first_index may be near 2^32 - 1.
  const std::uint64_t first = node.first_index;
  if (node.is_leaf())
    return out << " leaf: primitives " << first << " .. " << first + node.primitive_count - 1;
  return out << " inner: children " << first << ", " << first + 1 << ", split axis "
             << "xyz"[node.split_axis % 3];
}

Bvh4Node empty_bvh4_node() {
  Bvh4Node node;
  for (int i = 0; i < kBvh4Width; ++i) {
    node.min_x[i] = node.min_y[i] = node.min_z[i] = std::numeric_limits<float>::infinity();
    node.max_x[i] = node.max_y[i] = node.max_z[i] = -std::numeric_limits<float>::infinity();
    node.child[i] = 0;
    node.primitive_count[i] = 0;
  }
  node.child_count = 0;
  return node;
}

float bvh_sah_cost(const Bvh& bvh, float traversal_cost, float primitive_cost) {
  if (bvh.nodes.empty()) return 0.0f;
  const double root_area = bvh.nodes[0].bounds.surface_area();
  if (!(root_area > 0.0)) return primitive_cost * static_cast<float>(bvh.primitive_order.size());
  double cost = 0.0;
  for (const BvhNode& node : bvh.nodes) {
    const double weight = node.bounds.surface_area() / root_area;
    cost += weight * (node.is_leaf() ? primitive_cost * node.primitive_count : traversal_cost);
  }
  return static_cast<float>(cost);
}

namespace {

using Rule = BvhViolation::Rule;

BvhViolation violation(Rule rule, std::uint64_t index = 0, std::uint64_t value = 0, std::uint64_t count = 0,
                       std::uint64_t limit = 0, Bounds3 box = {}, Bounds3 other_box = {}) {
  BvhViolation v;
  v.rule = rule;
  v.index = index;
  v.value = value;
  v.count = count;
  v.limit = limit;
  v.box = box;
  v.other_box = other_box;
  return v;
}

// Walks the tree from the root with an explicit stack (a broken tree may be very deep or
// cyclic), calling visit(node_index, depth). Returns nullopt or the first problem found.
// Index arithmetic on a node read from a student's tree is done in 64 bits: first_index + 1
// wraps around to 0 in 32 bits when first_index is 0xFFFFFFFF.
template <typename Visit>
std::optional<BvhViolation> walk(const Bvh& bvh, Visit&& visit) {
  struct Entry {
    std::uint32_t node;
    int depth;
  };
  std::vector<Entry> stack{{0, 0}};
  std::vector<bool> seen(bvh.nodes.size(), false);
  while (!stack.empty()) {
    const Entry entry = stack.back();
    stack.pop_back();
    if (seen[entry.node]) return violation(Rule::ReachedTwice, entry.node);
    seen[entry.node] = true;
    const BvhNode& node = bvh.nodes[entry.node];
    if (std::optional<BvhViolation> problem = visit(entry.node, entry.depth)) return problem;
    if (!node.is_leaf()) {
      const std::uint64_t first_child = node.first_index;
      if (first_child <= entry.node || first_child + 1 >= bvh.nodes.size())
        return violation(Rule::BadChildren, entry.node, first_child, 0, bvh.nodes.size());
      stack.push_back({node.first_index, entry.depth + 1});
      stack.push_back({node.first_index + 1, entry.depth + 1});
    }
  }
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (!seen[i]) return violation(Rule::Unreached, i);
  return std::nullopt;
}

std::string box_words(const Bounds3& box) {
  std::ostringstream out;
  out << box;
  return out.str();
}

}  // namespace

int bvh_depth(const Bvh& bvh) {
  if (bvh.nodes.empty()) return -1;
  int deepest = 0;
  // A tree that fails bvh_invariant_violation may not be walkable; report what was reached.
  walk(bvh, [&](std::uint32_t, int depth) {
    deepest = std::max(deepest, depth);
    return std::optional<BvhViolation>();
  });
  return deepest;
}

std::optional<BvhViolation> find_bvh_violation(const Bvh& bvh, const std::vector<Bounds3>& primitive_bounds,
                                               int max_leaf_size) {
  const std::size_t n = primitive_bounds.size();
  if (bvh.primitive_order.size() != n) return violation(Rule::OrderSize, 0, 0, bvh.primitive_order.size(), n);
  std::vector<bool> listed(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t p = bvh.primitive_order[i];
    if (p >= n) return violation(Rule::OrderOutOfRange, i, p, 0, n);
    if (listed[p]) return violation(Rule::OrderTwice, i, p, 0, n);
    listed[p] = true;
  }
  if (n == 0) return bvh.nodes.empty() ? std::nullopt : std::optional(violation(Rule::NodesWithoutPrimitives));
  if (bvh.nodes.empty()) return violation(Rule::NoNodes, 0, 0, 0, n);

  std::vector<bool> in_a_leaf(n, false);
  const auto walk_problem = walk(bvh, [&](std::uint32_t index, int depth) -> std::optional<BvhViolation> {
    const BvhNode& node = bvh.nodes[index];
    if (depth >= kBvhMaxDepth) return violation(Rule::TooDeep, index, std::uint64_t(depth), 0, kBvhMaxDepth);
    if (node.is_leaf()) {
      if (node.primitive_count > max_leaf_size)
        return violation(Rule::LeafTooBig, index, 0, node.primitive_count, std::uint64_t(max_leaf_size));
      if (std::uint64_t(node.first_index) + node.primitive_count > n)
        return violation(Rule::LeafPastEnd, index, node.first_index, node.primitive_count, n);
      for (std::uint32_t i = node.first_index; i < node.first_index + node.primitive_count; ++i) {
        const std::uint32_t p = bvh.primitive_order[i];
        if (in_a_leaf[p]) return violation(Rule::PrimitiveInTwoLeaves, 0, p);
        in_a_leaf[p] = true;
        if (!node.bounds.contains(primitive_bounds[p]))
          return violation(Rule::LeafBoxTooSmall, index, p, 0, 0, node.bounds, primitive_bounds[p]);
      }
    } else {
      if (node.split_axis > 2) return violation(Rule::BadSplitAxis, index, node.split_axis);
      for (std::uint64_t child = node.first_index; child < std::uint64_t(node.first_index) + 2 && child < bvh.nodes.size(); ++child)
        if (!node.bounds.contains(bvh.nodes[child].bounds))
          return violation(Rule::ChildBoxTooSmall, index, child, 0, 0, node.bounds, bvh.nodes[child].bounds);
    }
    return std::nullopt;
  });
  if (walk_problem) return walk_problem;
  for (std::size_t p = 0; p < n; ++p)
    if (!in_a_leaf[p]) return violation(Rule::PrimitiveInNoLeaf, 0, p);
  return std::nullopt;
}

std::string describe(const BvhViolation& v) {
  const std::string index = std::to_string(v.index), value = std::to_string(v.value), count = std::to_string(v.count),
                    limit = std::to_string(v.limit);
  switch (v.rule) {
    case Rule::OrderSize: return "primitive_order has " + count + " entries, expected " + limit;
    case Rule::OrderOutOfRange:
      return "primitive_order[" + index + "] = " + value + " is out of range: expected a permutation of 0.." +
             std::to_string(v.limit - 1);
    case Rule::OrderTwice:
      return "primitive_order[" + index + "] = " + value + " appears twice: expected a permutation of 0.." +
             std::to_string(v.limit - 1);
    case Rule::NodesWithoutPrimitives: return "no primitives, but the tree has nodes";
    case Rule::NoNodes: return "no nodes for " + limit + " primitives";
    case Rule::TooDeep: return "node " + index + " is at depth " + value + ", expected below kBvhMaxDepth = " + limit;
    case Rule::LeafTooBig:
      return "leaf " + index + " holds " + count + " primitives, expected at most max_leaf_size = " + limit;
    case Rule::LeafPastEnd:
      return "leaf " + index + " lists primitive_order[" + value + " .. " + std::to_string(v.value + v.count - 1) +
             "], past its end (" + limit + ")";
    case Rule::PrimitiveInTwoLeaves: return "primitive " + value + " is in two leaves";
    case Rule::LeafBoxTooSmall:
      return "leaf " + index + " has bounds " + box_words(v.box) + " which do not hold primitive " + value + "'s box " +
             box_words(v.other_box);
    case Rule::BadSplitAxis: return "inner node " + index + " has split_axis " + value + ", expected 0, 1 or 2";
    case Rule::ChildBoxTooSmall:
      return "inner node " + index + " has bounds " + box_words(v.box) + " which do not hold child " + value + "'s " +
             box_words(v.other_box);
    case Rule::ReachedTwice: return "node " + index + " is reached twice from the root";
    case Rule::BadChildren: {
      std::string text = "inner node " + index + " has children " + value + " and " + std::to_string(v.value + 1) +
                         ", expected indices after it and below " + limit;
      if (v.value == 0)
        text += " (first_index 0 and primitive_count 0 are a new node's values: was this node written through a "
                "BvhNode& taken before a nodes.push_back? The vector grew and moved, and the write went to the old "
                "array: refer to nodes by index)";
      return text;
    }
    case Rule::Unreached: return "node " + index + " is never reached from the root";
    case Rule::PrimitiveInNoLeaf: return "primitive " + value + " is in no leaf";
  }
  return "";
}

BrokenBvh::BrokenBvh(const BvhViolation& broken_rule, std::uint64_t box_count,
                     const std::optional<std::string>& mesh_name)
    : std::logic_error("stage 05_bvh: build_bvh over " + std::to_string(box_count) + " boxes (" +
                       mesh_name.value_or("the scene's objects") +
                       ") returned a broken tree: " + describe(broken_rule) + " (the autograder's stage 5 tests say more)"),
      violation(broken_rule),
      boxes(box_count),
      mesh(mesh_name) {}

std::string bvh_invariant_violation(const Bvh& bvh, const std::vector<Bounds3>& primitive_bounds,
                                    int max_leaf_size) {
  const std::optional<BvhViolation> violation = find_bvh_violation(bvh, primitive_bounds, max_leaf_size);
  return violation ? describe(*violation) : "";
}

}  // namespace raylab
