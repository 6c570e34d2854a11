// The stage trees behind MeshTree (mesh_trees.h): the binary trees of stages 05 and 05b, the
// 4-wide tree of stage 05c, the KD-tree of stage 05d; the checks that a student's tree would not
// send its traversal out of its arrays; and the probe that finds a stub before the render starts.
#include "mesh_trees.h"

#include "raylab/bvh_tools.h"
#include "raylab/error.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/05c_wide_bvh.h"
#include "raylab/stages/05d_kdtree.h"

#include <stdexcept>
#include <utility>

namespace raylab {

namespace {

// A student's collapse_bvh4 may return a tree that would send intersect_bvh4 out of its arrays:
// what is wrong with it, in words, or nullopt.
std::optional<std::string> wide_tree_problem(const Bvh4& wide, std::size_t primitive_count) {
  if (wide.primitive_order.size() != primitive_count)
    return "its primitive_order holds " + std::to_string(wide.primitive_order.size()) + " entries, not " +
           std::to_string(primitive_count);
  std::vector<bool> seen(primitive_count, false);
  for (const std::uint32_t primitive : wide.primitive_order) {
    if (primitive >= primitive_count || seen[primitive]) return "its primitive_order is not each primitive once";
    seen[primitive] = true;
  }
  if (wide.nodes.empty()) return primitive_count == 0 ? std::nullopt : std::optional<std::string>("it has no nodes");
  // Every node reached once from the root (as stage 05c's contract asks), each slot in range.
  std::vector<bool> reached(wide.nodes.size(), false);
  std::vector<std::uint32_t> stack{0};
  reached[0] = true;
  while (!stack.empty()) {
    const std::uint32_t n = stack.back();
    stack.pop_back();
    const Bvh4Node& node = wide.nodes[n];
    if (node.child_count < 1 || node.child_count > kBvh4Width)
      return "node " + std::to_string(n) + " has " + std::to_string(node.child_count) + " children";
    for (int slot = 0; slot < node.child_count; ++slot) {
      if (node.is_leaf(slot)) {
        if (std::uint64_t(node.child[slot]) + node.primitive_count[slot] > primitive_count)
          return "a leaf of node " + std::to_string(n) + " reaches past primitive_order";
        continue;
      }
      const std::uint32_t child = node.child[slot];
      if (child == 0 || child >= wide.nodes.size() || reached[child])
        return "node " + std::to_string(n) + " names child node " + std::to_string(child) +
               " (each node but the root must be one node's child, once, within the nodes)";
      reached[child] = true;
      stack.push_back(child);
    }
  }
  return std::nullopt;
}

// A student's build_kdtree may return a tree that would send intersect_kdtree out of its arrays
// (or past the stack of kKdMaxDepth cells its contract promises): what is wrong with it, in words,
// or nullopt.
std::optional<std::string> kd_tree_problem(const KdTree& tree, std::size_t primitive_count) {
  if (tree.nodes.empty()) return primitive_count == 0 ? std::nullopt : std::optional<std::string>("it has no nodes");
  std::vector<bool> reached(tree.nodes.size(), false);
  std::vector<std::pair<std::uint32_t, int>> stack{{0u, 0}};
  reached[0] = true;
  while (!stack.empty()) {
    const auto [n, depth] = stack.back();
    stack.pop_back();
    const KdNode& node = tree.nodes[n];
    if (depth > kKdMaxDepth) return "node " + std::to_string(n) + " lies deeper than kKdMaxDepth";
    if (node.is_leaf()) {
      if (std::uint64_t(node.first_index) + node.primitive_count > tree.primitive_indices.size())
        return "leaf " + std::to_string(n) + " reaches past primitive_indices";
      for (std::uint32_t i = node.first_index; i < node.first_index + node.primitive_count; ++i)
        if (tree.primitive_indices[i] >= primitive_count)
          return "leaf " + std::to_string(n) + " lists primitive " + std::to_string(tree.primitive_indices[i]) +
                 " of " + std::to_string(primitive_count);
      continue;
    }
    if (node.split_axis > 2) return "node " + std::to_string(n) + " has split_axis " + std::to_string(node.split_axis);
    const std::uint64_t first = node.first_index;
    if (first == 0 || first + 1 >= tree.nodes.size() || reached[first] || reached[first + 1])
      return "node " + std::to_string(n) + " names children " + std::to_string(first) + " and " +
             std::to_string(first + 1) + " (each node but the root must be one node's child, once, within the nodes)";
    reached[first] = reached[first + 1] = true;
    stack.push_back({static_cast<std::uint32_t>(first), depth + 1});
    stack.push_back({static_cast<std::uint32_t>(first + 1), depth + 1});
  }
  return std::nullopt;
}

// A ray from `inside` along +z, and tests that hit nothing: only the stage's box tests and
// traversal run (a probe).
Ray probe_ray(const glm::vec3& inside) {
  Ray probe;
  probe.origin = inside;
  probe.direction = glm::vec3(0.0f, 0.0f, 1.0f);
  return probe;
}
const PrimitiveIntersector kHitsNothing{
    [](void*, const Ray&, std::uint32_t) -> std::optional<float> { return std::nullopt; }, nullptr};

std::size_t bytes_of(const Bvh& bvh) { return bvh.nodes.size() * sizeof(BvhNode) + bvh.primitive_order.size() * 4; }

// Stages 05 and 05b: a binary BVH, traversed by intersect_bvh.
class BinaryMeshTree final : public MeshTree {
 public:
  explicit BinaryMeshTree(Bvh bvh) : bvh_(std::move(bvh)) {}
  std::optional<BvhHit> traverse(const Ray& ray, const PrimitiveIntersector& tests, bool any_hit,
                                 BvhTraversalStats& stats) const override {
    return intersect_bvh(bvh_, ray, tests, any_hit, stats);
  }
  void probe() const override { probe_binary_tree(bvh_); }
  std::size_t bytes() const override { return bytes_of(bvh_); }
  const Bvh* binary_tree() const override { return &bvh_; }

 private:
  Bvh bvh_;
};

// Stage 05c: the binary tree collapsed to 4 wide by collapse_bvh4 (checked), traversed by
// intersect_bvh4. The binary tree is kept for the view and the trace.
class WideMeshTree final : public MeshTree {
 public:
  WideMeshTree(Bvh binary, const std::string& name) : binary_(std::move(binary)), wide_(collapse_bvh4(binary_)) {
    if (const std::optional<std::string> problem = wide_tree_problem(wide_, binary_.primitive_order.size()))
      throw std::runtime_error("stage 05c_wide_bvh: collapse_bvh4 over the tree of " + name +
                               " returned a broken tree: " + *problem);
  }
  std::optional<BvhHit> traverse(const Ray& ray, const PrimitiveIntersector& tests, bool any_hit,
                                 BvhTraversalStats& stats) const override {
    return intersect_bvh4(wide_, ray, tests, any_hit, stats);
  }
  void probe() const override {
    BvhTraversalStats stats;
    (void)intersect_bvh4(wide_, probe_ray(wide_.nodes[0].child_bounds(0).centroid()), kHitsNothing, false, stats);
  }
  std::size_t bytes() const override {
    return bytes_of(binary_) + wide_.nodes.size() * sizeof(Bvh4Node) + wide_.primitive_order.size() * 4;
  }
  const Bvh* binary_tree() const override { return &binary_; }

 private:
  Bvh binary_;
  Bvh4 wide_;
};

// Stage 05d: a KD-tree over the triangles, traversed by intersect_kdtree.
class KdMeshTree final : public MeshTree {
 public:
  explicit KdMeshTree(KdTree tree) : tree_(std::move(tree)) {}
  std::optional<BvhHit> traverse(const Ray& ray, const PrimitiveIntersector& tests, bool any_hit,
                                 BvhTraversalStats& stats) const override {
    return intersect_kdtree(tree_, ray, tests, any_hit, stats);
  }
  void probe() const override {
    BvhTraversalStats stats;
    (void)intersect_kdtree(tree_, probe_ray(tree_.bounds.centroid()), kHitsNothing, false, stats);
  }
  std::size_t bytes() const override {
    return tree_.nodes.size() * sizeof(KdNode) + tree_.primitive_indices.size() * 4;
  }

 private:
  KdTree tree_;
};

}  // namespace

BinaryTreeBuild::BinaryTreeBuild(StageTree tree_) : tree(tree_), sah(tree_ == StageTree::Sah || tree_ == StageTree::Wide) {}

Bvh BinaryTreeBuild::build(const std::vector<Bounds3>& boxes, const std::optional<std::string>& name) {
  Bvh bvh;
  bool built = false;
  if (sah && tree == StageTree::Wide) {
    try {
      bvh = build_bvh_sah(boxes, SceneGeometry::kBvhLeafSize);
      built = true;
    } catch (const NotImplemented& error) {
      if (error.function() != "build_bvh_sah") throw;
      sah = false;
    }
  }
  if (!built) bvh = sah ? build_bvh_sah(boxes, SceneGeometry::kBvhLeafSize) : build_bvh(boxes, SceneGeometry::kBvhLeafSize);
  // A broken tree named by the stage whose build made it (BrokenBvh names stage 05's).
  if (const std::optional<BvhViolation> broken = find_bvh_violation(bvh, boxes, SceneGeometry::kBvhLeafSize)) {
    if (!sah) throw BrokenBvh(*broken, boxes.size(), name);
    throw std::runtime_error("stage 05b_bvh_sah: build_bvh_sah over " + std::to_string(boxes.size()) + " boxes (" +
                             name.value_or("the scene's objects") + ") returned a broken tree: " + describe(*broken));
  }
  return bvh;
}

std::unique_ptr<MeshTree> build_mesh_tree(BinaryTreeBuild& binary, const std::vector<Bounds3>& boxes,
                                          const std::string& name,
                                          const std::function<void(const std::vector<std::uint32_t>&)>& store_in_leaf_order) {
  if (binary.tree == StageTree::KdTree) {
    KdTree tree = build_kdtree(boxes);
    if (const std::optional<std::string> problem = kd_tree_problem(tree, boxes.size()))
      throw std::runtime_error("stage 05d_kdtree: build_kdtree over the triangles of " + name +
                               " returned a broken tree: " + *problem);
    return std::make_unique<KdMeshTree>(std::move(tree));
  }
  Bvh bvh = binary.build(boxes, name);
  store_in_leaf_order(bvh.primitive_order);
  for (std::uint32_t i = 0; i < bvh.primitive_order.size(); ++i) bvh.primitive_order[i] = i;
  if (binary.tree == StageTree::Wide) return std::make_unique<WideMeshTree>(std::move(bvh), name);
  return std::make_unique<BinaryMeshTree>(std::move(bvh));
}

void probe_binary_tree(const Bvh& bvh) {
  const Ray probe = probe_ray(bvh.nodes[0].bounds.centroid());  // inside the root's box
  (void)intersect_ray_box(probe, ray_direction_inverse_of(probe), bvh.nodes[0].bounds);
  BvhTraversalStats stats;
  (void)intersect_bvh(bvh, probe, kHitsNothing, /*any_hit=*/false, stats);
}

}  // namespace raylab
