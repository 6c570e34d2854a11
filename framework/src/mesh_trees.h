// One mesh's tree from the stages (05 median, 05b SAH, 05c 4-wide, 05d KD-tree) behind one
// interface, as pbrt-v4 puts every aggregate behind one: SceneGeometry builds one per mesh of more
// than a few triangles and asks it for the closest or any hit, giving it its own tests of the
// mesh's triangles (stage 05's PrimitiveIntersector, which records the hit's details). A new tree
// is one more class here; the geometry has no branch per tree. (A program's own tree over every
// triangle, raylab/accelerator.h, tests the triangles itself and is not one of these.)
// Private to framework/src (geometry_build.cpp builds them, geometry_bvh_adapters.cpp traverses).
#pragma once

#include "raylab/bounds.h"
#include "raylab/geometry.h"
#include "raylab/stages/05_bvh.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

class MeshTree {
 public:
  virtual ~MeshTree() = default;
  // The stage's traversal of the tree (intersect_bvh, intersect_bvh4 or intersect_kdtree) with
  // `tests` of the mesh's triangles, numbered as the boxes the tree was built over.
  virtual std::optional<BvhHit> traverse(const Ray& ray, const PrimitiveIntersector& tests, bool any_hit,
                                         BvhTraversalStats& stats) const = 0;
  // Calls the stage functions its traversal needs once, on a ray that hits nothing, so that a
  // stub throws NotImplemented now rather than in the middle of a render. (The 4-wide tree's
  // binary one is only drawn, never traversed: not probed.)
  virtual void probe() const = 0;
  // The memory of its nodes, primitive orders and leaf lists, in bytes.
  virtual std::size_t bytes() const = 0;
  // The binary tree that `raylab view` draws and `raylab trace` walks down (the 4-wide tree's is
  // the one it was collapsed from); nullptr for the KD-tree.
  virtual const Bvh* binary_tree() const { return nullptr; }
};

// How the binary trees of a render are built: stage 05's median split (build_bvh) or stage 05b's
// SAH (build_bvh_sah), each tree checked before use.
struct BinaryTreeBuild {
  // For `tree`: the SAH build for Sah, and for Wide while build_bvh_sah is written (see `build`);
  // else the median build.
  explicit BinaryTreeBuild(StageTree tree);
  // The tree over `boxes`; `name` is what they are the boxes of (a mesh's name, or nullopt for the
  // scene's objects), for the error a broken tree gives (std::runtime_error or BrokenBvh, naming
  // the stage whose build made it). For Wide, a stub build_bvh_sah makes this and every later
  // build the median one.
  Bvh build(const std::vector<Bounds3>& boxes, const std::optional<std::string>& name);
  StageTree tree;
  bool sah;  // whether the trees are the SAH build's
};

// One mesh's tree of kind binary.tree (Median, Sah, Wide or KdTree) over the boxes of its
// triangles, checked: a stub throws NotImplemented, a tree that would send its traversal out of
// its arrays a std::runtime_error naming the stage, `name` (the mesh) and the broken rule.
// A binary tree (Median, Sah, Wide) calls store_in_leaf_order with its primitive_order, which it
// then makes the identity: the caller stores the triangles in that order, so that a leaf's
// triangles are adjacent in memory (and the 4-wide tree is collapsed after). A KD-tree's leaves
// list the triangles in the order they were given.
std::unique_ptr<MeshTree> build_mesh_tree(BinaryTreeBuild& binary, const std::vector<Bounds3>& boxes,
                                          const std::string& name,
                                          const std::function<void(const std::vector<std::uint32_t>&)>& store_in_leaf_order);

// Calls stage 04's box test and stage 05's intersect_bvh once on `bvh` (not empty), on a ray that
// hits nothing (MeshTree::probe of the binary trees, and of the tree over the objects).
void probe_binary_tree(const Bvh& bvh);

}  // namespace raylab
