// The framework's side of stages 04_box and 05_bvh: printing, and measuring and checking a
// built tree (SAH cost, depth, invariants) for the renderer, bench/ and the autograder.
#include "raylab/bounds.h"
#include "raylab/bvh_tools.h"
#include "raylab/stages/05_bvh.h"

#include <algorithm>
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

// Walks the tree from the root with an explicit stack (a broken tree may be very deep or
// cyclic), calling visit(node_index, depth). Returns "" or the first problem found.
// Index arithmetic on a node read from a student's tree is done in 64 bits: first_index + 1
// wraps around to 0 in 32 bits when first_index is 0xFFFFFFFF.
template <typename Visit>
std::string walk(const Bvh& bvh, Visit&& visit) {
  struct Entry {
    std::uint32_t node;
    int depth;
  };
  std::vector<Entry> stack{{0, 0}};
  std::vector<bool> seen(bvh.nodes.size(), false);
  while (!stack.empty()) {
    const Entry entry = stack.back();
    stack.pop_back();
    std::ostringstream problem;
    if (seen[entry.node]) {
      problem << "node " << entry.node << " is reached twice from the root";
      return problem.str();
    }
    seen[entry.node] = true;
    const BvhNode& node = bvh.nodes[entry.node];
    std::string message = visit(entry.node, entry.depth);
    if (!message.empty()) return message;
    if (!node.is_leaf()) {
      const std::uint64_t first_child = node.first_index;
      if (first_child <= entry.node || first_child + 1 >= bvh.nodes.size()) {
        problem << "inner node " << entry.node << " has children " << first_child << " and "
                << first_child + 1 << ", expected indices after it and below " << bvh.nodes.size();
        if (first_child == 0)
          problem << " (first_index 0 and primitive_count 0 are a new node's values: was this node"
                     " written through a BvhNode& taken before a nodes.push_back? The vector grew and"
                     " moved, and the write went to the old array: refer to nodes by index)";
        return problem.str();
      }
      stack.push_back({node.first_index, entry.depth + 1});
      stack.push_back({node.first_index + 1, entry.depth + 1});
    }
  }
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (!seen[i]) return "node " + std::to_string(i) + " is never reached from the root";
  return "";
}

}  // namespace

int bvh_depth(const Bvh& bvh) {
  if (bvh.nodes.empty()) return -1;
  int deepest = 0;
  // A tree that fails bvh_invariant_violation may not be walkable; report what was reached.
  walk(bvh, [&](std::uint32_t, int depth) {
    deepest = std::max(deepest, depth);
    return std::string();
  });
  return deepest;
}

std::string bvh_invariant_violation(const Bvh& bvh, const std::vector<Bounds3>& primitive_bounds,
                                    int max_leaf_size) {
  std::ostringstream problem;
  const std::size_t n = primitive_bounds.size();
  if (bvh.primitive_order.size() != n) {
    problem << "primitive_order has " << bvh.primitive_order.size() << " entries, expected " << n;
    return problem.str();
  }
  std::vector<bool> listed(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t p = bvh.primitive_order[i];
    if (p >= n || listed[p]) {
      problem << "primitive_order[" << i << "] = " << p
              << (p >= n ? " is out of range" : " appears twice") << ": expected a permutation of 0.."
              << n - 1;
      return problem.str();
    }
    listed[p] = true;
  }
  if (n == 0) return bvh.nodes.empty() ? "" : "no primitives, but the tree has nodes";
  if (bvh.nodes.empty()) return "no nodes for " + std::to_string(n) + " primitives";

  std::vector<bool> in_a_leaf(n, false);
  const std::string walk_problem = walk(bvh, [&](std::uint32_t index, int depth) -> std::string {
    const BvhNode& node = bvh.nodes[index];
    std::ostringstream out;
    if (depth >= kBvhMaxDepth) {
      out << "node " << index << " is at depth " << depth << ", expected below kBvhMaxDepth = " << kBvhMaxDepth;
      return out.str();
    }
    if (node.is_leaf()) {
      if (node.primitive_count > max_leaf_size) {
        out << "leaf " << index << " holds " << node.primitive_count
            << " primitives, expected at most max_leaf_size = " << max_leaf_size;
        return out.str();
      }
      if (std::uint64_t(node.first_index) + node.primitive_count > n) {
        out << "leaf " << index << " lists primitive_order[" << node.first_index << " .. "
            << std::uint64_t(node.first_index) + node.primitive_count - 1 << "], past its end (" << n << ")";
        return out.str();
      }
      for (std::uint32_t i = node.first_index; i < node.first_index + node.primitive_count; ++i) {
        const std::uint32_t p = bvh.primitive_order[i];
        if (in_a_leaf[p]) {
          out << "primitive " << p << " is in two leaves";
          return out.str();
        }
        in_a_leaf[p] = true;
        if (!node.bounds.contains(primitive_bounds[p])) {
          out << "leaf " << index << " has bounds " << node.bounds << " which do not hold primitive "
              << p << "'s box " << primitive_bounds[p];
          return out.str();
        }
      }
    } else {
      if (node.split_axis > 2) {
        out << "inner node " << index << " has split_axis " << int(node.split_axis) << ", expected 0, 1 or 2";
        return out.str();
      }
      for (std::uint64_t child = node.first_index; child < std::uint64_t(node.first_index) + 2 && child < bvh.nodes.size(); ++child)
        if (!node.bounds.contains(bvh.nodes[child].bounds)) {
          out << "inner node " << index << " has bounds " << node.bounds << " which do not hold child "
              << child << "'s " << bvh.nodes[child].bounds;
          return out.str();
        }
    }
    return "";
  });
  if (!walk_problem.empty()) return walk_problem;
  for (std::size_t p = 0; p < n; ++p)
    if (!in_a_leaf[p]) return "primitive " + std::to_string(p) + " is in no leaf";
  return "";
}

}  // namespace raylab
