// The reference's fastest tree over every triangle of a scene, as raylab-reference and bench/
// hand it to the renderer (TracingFunctions::own_tree, raylab/accelerator.h): the reference's
// SAH build (stage 05b) collapsed to 8 wide with AVX2 box tests where the CPU has it
// (wide8.h), else to 4 wide (stage 05c), its leaves' triangles tested with the reference's own
// Moller-Trumbore inlined, several at a time (solutions/05_bvh/leaf_test.h). One type per layout.
// The same closest t as testing every triangle with stage 03's test, and the same bits of t and
// barycentrics (the triangle found may differ on a tie). Counts no work. Not part of any
// student contract; linked only into the programs that link solutions/.
#pragma once

#include "../05_bvh/leaf_test.h"
#include "wide8.h"

#include "raylab/accelerator.h"
#include "raylab/stages/05_bvh.h"
#include "raylab/stages/05c_wide_bvh.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raylab::reference {

// What both layouts start from: the SAH tree over the triangles' boxes (leaves of at most 4,
// as the renderer's stage trees), the triangles as edges in the caller's order, and as
// columns in the tree's leaf order. The trees keep the binary tree's primitive_order, so a hit
// names the caller's triangle.
struct FastTreeTriangles {
  static constexpr int kLeafSize = 4;
  Bvh binary;
  std::vector<TriangleEdges> edges;
  std::vector<float> columns;

  explicit FastTreeTriangles(const std::vector<glm::vec3>& corners) {
    std::vector<Bounds3> boxes(corners.size() / 3);
    edges.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const glm::vec3* p = corners.data() + 3 * i;
      boxes[i].extend(p[0]);
      boxes[i].extend(p[1]);
      boxes[i].extend(p[2]);
      edges.push_back(TriangleEdges::of(p[0], p[1], p[2]));
    }
    binary = build_bvh_sah(boxes, kLeafSize);
    columns = triangle_columns(edges.data(), binary.primitive_order);
  }
};

// Stage 05c's 4-wide tree, four triangles at a time.
class FourWideTree final : public TriangleTree {
 public:
  explicit FourWideTree(const std::vector<glm::vec3>& corners) : triangles_(corners) {
    tree_ = collapse_bvh4(triangles_.binary);
  }
  std::string name() const override { return "the reference's own (SAH, 4 wide)"; }
  bool closest_hit(const Ray& ray, std::uint32_t& triangle, TriangleHit& hit) const override {
    BvhTraversalStats uncounted;
    const LeafTriangles leaves{triangles_.edges.data(), TriangleColumns::of(triangles_.columns), &hit};
    const std::optional<BvhHit> found = intersect_bvh4_inlined(tree_, ray, leaves, /*any_hit=*/false, uncounted);
    if (found) triangle = found->primitive;
    return found.has_value();
  }
  std::optional<float> any_hit(const Ray& ray) const override {
    BvhTraversalStats uncounted;
    const LeafTriangles leaves{triangles_.edges.data(), TriangleColumns::of(triangles_.columns), nullptr};
    const std::optional<BvhHit> found = intersect_bvh4_inlined(tree_, ray, leaves, /*any_hit=*/true, uncounted);
    return found ? std::optional<float>(found->t_hit) : std::nullopt;
  }

 private:
  FastTreeTriangles triangles_;
  Bvh4 tree_;
};

#if RAYLAB_AVX2_COMPILES
// The 8-wide tree (wide8.h), eight triangles at a time; only where the CPU runs AVX2. Its
// queries are flattened: the traversal is inlined, so that its hit is not handed back through
// memory (docs/performance.md, "Stores read back whole").
class EightWideTree final : public TriangleTree {
 public:
  explicit EightWideTree(const std::vector<glm::vec3>& corners) : triangles_(corners) {
    if (!triangles_.binary.nodes.empty()) tree_ = collapse_bvh8(triangles_.binary);
  }
  std::string name() const override { return "the reference's own (SAH, 8 wide)"; }
  __attribute__((target("avx2"), flatten)) bool closest_hit(const Ray& ray, std::uint32_t& triangle,
                                                            TriangleHit& hit) const override {
    if (tree_.nodes.empty()) return false;
    BvhTraversalStats uncounted;
    const std::optional<BvhHit> found =
        traverse8<false>(tree_, ray, uncounted, EightAtATime{tree_.primitive_order.data(), columns(), &hit});
    if (found) triangle = found->primitive;
    return found.has_value();
  }
  __attribute__((target("avx2"), flatten)) std::optional<float> any_hit(const Ray& ray) const override {
    if (tree_.nodes.empty()) return std::nullopt;
    BvhTraversalStats uncounted;
    const std::optional<BvhHit> found =
        traverse8<true>(tree_, ray, uncounted, EightAtATime{tree_.primitive_order.data(), columns(), nullptr});
    return found ? std::optional<float>(found->t_hit) : std::nullopt;
  }

 private:
  TriangleColumns columns() const { return TriangleColumns::of(triangles_.columns); }
  FastTreeTriangles triangles_;
  Bvh8 tree_;
};
#endif

// Builders for TracingFunctions::own_tree: the 4-wide tree; the 8-wide tree where it runs, else
// the 4-wide one (what raylab-reference and bench/ trace).
inline std::unique_ptr<TriangleTree> build_four_wide_tree(const std::vector<glm::vec3>& corners) {
  return std::make_unique<FourWideTree>(corners);
}
inline std::unique_ptr<TriangleTree> build_fast_tree(const std::vector<glm::vec3>& corners) {
#if RAYLAB_AVX2_COMPILES
  if (eight_wide_tree_runs_here()) return std::make_unique<EightWideTree>(corners);
#endif
  return std::make_unique<FourWideTree>(corners);
}

}  // namespace raylab::reference
