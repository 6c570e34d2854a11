// Stage 05d_kdtree (bonus): a KD-tree.  Handout: docs/05d_kdtree.md
//
// A BVH groups the primitives and lets their boxes overlap. A KD-tree does the opposite: it cuts
// space into cells by axis-aligned planes, the cells never overlap, and a primitive that crosses a
// plane is listed on both sides. A ray then walks the cells it crosses in order, nearest first,
// and can stop at the first cell that holds a hit. You write two functions:
//
//   build_kdtree      the boxes of the primitives -> the tree, each plane chosen by the SAH
//   intersect_kdtree  stage 05's traversal, through the cells of the tree
//
// WHAT YOU GET
//   KdNode, KdTree, kKdMaxDepth, kKdEmptyBonus, kdtree_max_depth (raylab/stages/05d_kdtree.h):
//     the layout and the costs. Read the comment above KdNode: which child is below the plane.
//   Bounds3 (raylab/bounds.h): extend, surface_area, extent.
//   PrimitiveIntersector, BvhTraversalStats, BvhHit (stage 05): as intersect_bvh uses them.
//
// THE RULES
//   - build_kdtree: the root's cell is the union of the primitives' boxes (tree.bounds); a
//     primitive with an empty box is in no leaf. Each inner node's plane is the cheapest by the
//     SAH cost in raylab/stages/05d_kdtree.h, among planes strictly inside the cell (at the boxes'
//     faces: handout section 3); a node is a leaf when no plane costs less than the leaf, or at
//     depth kdtree_max_depth(primitive count) (and a tree over n primitives has at most 16 n + 1
//     nodes). A primitive goes below the plane when its box has
//     min < split_position, above when max > split_position (both when it crosses the plane), and
//     to one side when its box lies in the plane. Every leaf lists every primitive whose box
//     reaches into its cell: one lost at a split is one the ray can never hit.
//   - intersect_kdtree gives stage 05's answers. It clips the ray's interval [t_min, t_max] to
//     tree.bounds, then walks the cells front to back: at an inner node, the child on the ray's
//     side of the plane first, with the interval cut at the plane (t_split), the other child
//     afterwards with the rest, and only the children the interval reaches. At a leaf it tests
//     its primitives and keeps the closest hit so far; the walk ends when that hit lies inside the
//     leaf's cell (t_hit <= the leaf's interval end), or when the next cell starts beyond it. One
//     exception: a ray that lies in a plane walks both of its sides over the same interval, so
//     while the second side waits the walk only skips cells that start beyond the hit, and walks
//     that side before it ends. A ray that misses tree.bounds visits no node. With any_hit it returns the first hit found. stats.nodes_visited counts every
//     node stepped into, stats.primitives_tested every intersector.test call.
//
// READ docs/05d_kdtree.md: section 1 (cells, not groups), 2 (the layout), 3 (the SAH over planes,
//   and the sweep that prices every plane of an axis in one pass), 4 (the walk, front to back),
//   5 (KD-tree or BVH: measure it with raylab bench), 6 (common mistakes, which the autograder's
//   hints name).
//
// HOW TO CHECK
//   build/bin/autograder --stage 05d_kdtree
//   build/bin/raylab render scenes/bunny.json --accel kdtree -o bunny.png
#include "raylab/error.h"
#include "raylab/stages/05d_kdtree.h"

namespace raylab {

// RETURN the KD-tree over the boxes of the primitives (handout section 3).
KdTree build_kdtree(const std::vector<Bounds3>& primitive_bounds) {
  (void)primitive_bounds;
  // Delete the line below when you write the function (handout section 3).
  throw NotImplemented("build_kdtree");
}

// RETURN the closest hit (any_hit false) or the first hit found (any_hit true) through the cells
// of the tree, nullopt when nothing is hit; add the work to `stats` (handout section 4).
std::optional<BvhHit> intersect_kdtree(const KdTree& tree, const Ray& ray, const PrimitiveIntersector& intersector,
                                       bool any_hit, BvhTraversalStats& stats) {
  (void)tree;
  (void)ray;
  (void)intersector;
  (void)any_hit;
  (void)stats;
  throw NotImplemented("intersect_kdtree");
}

}  // namespace raylab
