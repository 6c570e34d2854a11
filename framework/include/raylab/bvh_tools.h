// The framework's BVH tools (framework/src/bvh.cpp; not part of the assignment): what the
// renderer, the autograder, the tests and bench/ measure and check about a built tree.
#pragma once

#include "raylab/stages/05_bvh.h"

#include <cstdint>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab {

// The surface area heuristic cost of a tree: the expected work of a random ray that hits the
// root, sum over nodes of area(node) / area(root) * (traversal_cost for an inner node, or
// primitive_cost * primitive_count for a leaf). Lower is better; 0 for an empty tree.
float bvh_sah_cost(const Bvh& bvh, float traversal_cost = 1.0f, float primitive_cost = 1.0f);

// The depth of the deepest leaf (root = 0); -1 for an empty tree.
int bvh_depth(const Bvh& bvh);

// A rule of every correct BVH that a tree breaks, with the numbers that show it (the fields
// each rule uses are named beside it; describe() writes it in English, the autograder in the
// student's language from the same fields).
struct BvhViolation {
  enum class Rule : std::uint8_t {
    OrderSize,               // primitive_order has `count` entries, expected `limit`
    OrderOutOfRange,         // primitive_order[`index`] = `value`, not below `limit`
    OrderTwice,              // primitive_order[`index`] = `value` appears twice (`limit` primitives)
    NodesWithoutPrimitives,  // no primitives, but nodes
    NoNodes,                 // no nodes for `limit` primitives
    TooDeep,                 // node `index` at depth `value`, not below `limit` (kBvhMaxDepth)
    LeafTooBig,              // leaf `index` holds `count` primitives, more than `limit` (max_leaf_size)
    LeafPastEnd,             // leaf `index` lists primitive_order[`value` .. `value` + `count` - 1], past `limit`
    PrimitiveInTwoLeaves,    // primitive `value`
    LeafBoxTooSmall,         // leaf `index`'s `box` does not hold primitive `value`'s `other_box`
    BadSplitAxis,            // inner node `index` has split_axis `value`
    ChildBoxTooSmall,        // inner node `index`'s `box` does not hold child `value`'s `other_box`
    ReachedTwice,            // node `index`
    BadChildren,             // inner node `index` has children `value`, `value` + 1, not after it and below `limit`
    Unreached,               // node `index` is never reached from the root
    PrimitiveInNoLeaf,       // primitive `value`
  };
  Rule rule = Rule::OrderSize;
  std::uint64_t index = 0, value = 0, count = 0, limit = 0;
  Bounds3 box, other_box;
};

// Checks what every correct builder guarantees, and returns the first broken rule (nullopt
// when all hold): primitive_order is a permutation of 0 .. n - 1; every node is reached
// exactly once from the root; children follow their parent in the array; an inner node's box
// holds its children's boxes and a leaf's box holds its primitives' boxes; leaves are not
// empty and hold at most max_leaf_size primitives; the depth is below kBvhMaxDepth.
std::optional<BvhViolation> find_bvh_violation(const Bvh& bvh, const std::vector<Bounds3>& primitive_bounds,
                                               int max_leaf_size);
// The rule in English words ("leaf 0 holds 100 primitives, expected at most max_leaf_size = 4").
std::string describe(const BvhViolation& violation);
// describe(*find_bvh_violation(...)), or "" when all rules hold.
std::string bvh_invariant_violation(const Bvh& bvh, const std::vector<Bounds3>& primitive_bounds,
                                    int max_leaf_size);

// What the renderer's geometry throws when the student's build_bvh returns a tree that breaks a
// rule (a traversal could run off its arrays): the rule, the number of boxes, and the mesh (its
// name, or nullopt for the tree over the scene's objects). what(): the same in English words.
class BrokenBvh : public std::logic_error {
 public:
  BrokenBvh(const BvhViolation& broken_rule, std::uint64_t box_count, const std::optional<std::string>& mesh_name);
  BvhViolation violation;
  std::uint64_t boxes;
  std::optional<std::string> mesh;  // nullopt: the tree over the scene's objects
};

std::ostream& operator<<(std::ostream& out, const BvhNode& node);

}  // namespace raylab
