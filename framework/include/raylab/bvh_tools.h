// The framework's BVH tools (framework/src/bvh.cpp; not part of the assignment): what the
// renderer, the autograder, the tests and bench/ measure and check about a built tree.
#pragma once

#include "raylab/stages/05_bvh.h"

#include <ostream>
#include <string>
#include <vector>

namespace raylab {

// The surface area heuristic cost of a tree: the expected work of a random ray that hits the
// root, sum over nodes of area(node) / area(root) * (traversal_cost for an inner node, or
// primitive_cost * primitive_count for a leaf). Lower is better; 0 for an empty tree.
float bvh_sah_cost(const Bvh& bvh, float traversal_cost = 1.0f, float primitive_cost = 1.0f);

// The depth of the deepest leaf (root = 0); -1 for an empty tree.
int bvh_depth(const Bvh& bvh);

// Checks what every correct builder guarantees, and returns the first broken rule in words
// ("" when all hold): primitive_order is a permutation of 0 .. n - 1; every node is reached
// exactly once from the root; children follow their parent in the array; an inner node's box
// holds its children's boxes and a leaf's box holds its primitives' boxes; leaves are not
// empty and hold at most max_leaf_size primitives; the depth is below kBvhMaxDepth.
std::string bvh_invariant_violation(const Bvh& bvh, const std::vector<Bounds3>& primitive_bounds,
                                    int max_leaf_size);

std::ostream& operator<<(std::ostream& out, const BvhNode& node);

}  // namespace raylab
