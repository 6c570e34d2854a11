// The reference BVH (solutions/05_bvh) beyond what the autograder's small meshes reach: trees
// of 64k primitives and more, whose top subtrees the reference builds on several threads, and
// the node array's cache-line layout that raylab/stages/05_bvh.h promises.
#include "raylab/mesh_generator.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/bvh_tools.h"
#include "raylab/stages/05_bvh.h"
#include "raylab/testkit/triangles.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>

namespace raylab {
namespace {

constexpr int kLeafSize = 4;

struct Mesh {
  TriangleMesh triangles;
  std::vector<Bounds3> boxes;
  const glm::vec3& corner(std::uint32_t triangle, int k) const {
    return triangles.positions[triangles.indices[3 * triangle + k]];
  }
};

// About 200k triangles: big enough for the multi-threaded build (at least 65536 per subtree).
const Mesh& large_mesh() {
  static const Mesh mesh = [] {
    Mesh m{make_displaced_sphere(200000, 1.0f, 7), {}};
    m.boxes.resize(m.triangles.indices.size() / 3);
    for (std::uint32_t t = 0; t < m.boxes.size(); ++t)
      for (int k = 0; k < 3; ++k) m.boxes[t].extend(m.corner(t, k));
    return m;
  }();
  return mesh;
}

void expect_sound_tree(const Bvh& bvh, const char* builder) {
  const Mesh& mesh = large_mesh();
  EXPECT_EQ(bvh_invariant_violation(bvh, mesh.boxes, kLeafSize), "") << builder;
  // Every node reached once and no gaps: a binary tree of L leaves has 2L - 1 nodes.
  std::size_t leaves = 0;
  for (const BvhNode& node : bvh.nodes) leaves += node.is_leaf() ? 1 : 0;
  EXPECT_EQ(bvh.nodes.size(), 2 * leaves - 1) << builder;

  // Closest hits of rays from outside towards the sphere, and random ones from inside.
  const testkit::IndexedTriangles triangles{&mesh.triangles.positions, &mesh.triangles.indices, &intersect_ray_triangle};
  const PrimitiveIntersector intersector = testkit::intersector_over(triangles);
  std::mt19937 random(5);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  int differences = 0;
  for (int r = 0; r < 60; ++r) {
    Ray ray;
    ray.origin = r % 2 ? glm::vec3(uniform(random), uniform(random), uniform(random)) * 0.3f
                       : glm::normalize(glm::vec3(uniform(random), uniform(random), uniform(random))) * 3.0f;
    const glm::vec3 target(uniform(random) * 0.5f, uniform(random) * 0.5f, uniform(random) * 0.5f);
    ray.direction = glm::normalize(r % 2 ? glm::vec3(uniform(random), uniform(random), uniform(random)) : target - ray.origin);
    BvhTraversalStats stats;
    const std::optional<BvhHit> got = intersect_bvh(bvh, ray, intersector, false, stats);
    const std::optional<BvhHit> expected =
        testkit::brute_force_hit(intersector, static_cast<std::uint32_t>(mesh.boxes.size()), ray);
    const bool same = got.has_value() == expected.has_value() && (!got || got->t_hit == expected->t_hit);
    if (!same) ++differences;
    EXPECT_TRUE(same) << builder << ", ray " << r << ": " << ray << ": BVH "
                      << (got ? std::to_string(got->t_hit) : "no hit") << ", brute force "
                      << (expected ? std::to_string(expected->t_hit) : "no hit");
    if (differences > 3) return;
  }
}

TEST(ReferenceBvh, LargeSahTreeIsSoundAndFindsTheClosestHits) {
  expect_sound_tree(build_bvh_sah(large_mesh().boxes, kLeafSize), "build_bvh_sah");
}

TEST(ReferenceBvh, LargeMedianTreeIsSoundAndFindsTheClosestHits) {
  expect_sound_tree(build_bvh(large_mesh().boxes, kLeafSize), "build_bvh");
}

TEST(ReferenceBvh, MultiThreadedBuildIsDeterministic) {
  // The subtrees built on other threads are appended in a fixed order: the same bytes each time.
  const Bvh first = build_bvh_sah(large_mesh().boxes, kLeafSize);
  for (int run = 0; run < 3; ++run) {
    const Bvh again = build_bvh_sah(large_mesh().boxes, kLeafSize);
    ASSERT_EQ(again.nodes.size(), first.nodes.size());
    EXPECT_EQ(std::memcmp(again.nodes.data(), first.nodes.data(), first.nodes.size() * sizeof(BvhNode)), 0);
    EXPECT_EQ(again.primitive_order, first.primitive_order);
  }
}

TEST(BvhNodeLayout, EverySiblingPairFillsOneCacheLine) {
  // Children are appended in pairs after the root, so pairs start at odd indices; the node
  // array's allocator puts nodes[1] at the start of a 64-byte line (05_bvh.h).
  const Bvh bvh = build_bvh_sah(large_mesh().boxes, kLeafSize);
  ASSERT_GT(bvh.nodes.size(), 2u);
  for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
    const BvhNode& node = bvh.nodes[i];
    if (node.is_leaf()) continue;
    ASSERT_EQ(node.first_index % 2, 1u) << "node " << i << "'s children start at an even index";
    const auto address = reinterpret_cast<std::uintptr_t>(&bvh.nodes[node.first_index]);
    ASSERT_EQ(address % 64, 0u) << "node " << i << "'s children do not start a cache line";
  }
  Bvh copied = bvh;  // copies and growth keep the layout: it is the allocator's
  copied.nodes.push_back(BvhNode{});
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(&copied.nodes[1]) % 64, 0u);
}

}  // namespace
}  // namespace raylab
