// The reference BVH (solutions/05_bvh) beyond what the autograder's small meshes reach: trees
// of 64k primitives and more, whose top subtrees the reference builds on several threads, the
// node array's cache-line layout that raylab/stages/05_bvh.h promises, and the reference
// traversal's inlined triangle test (reference::LeafTriangles), which must give the
// stage-03 calls' answers bit for bit, on adversarial rays too.
#include "raylab/mesh_generator.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/bvh_tools.h"
#include "raylab/stages/05_bvh.h"
#include "raylab/stages/05c_wide_bvh.h"
#include "raylab/stages/05d_kdtree.h"
#include "raylab/testkit/triangles.h"

#include "../solutions/05c_wide_bvh/wide8.h"  // the reference's 8-wide tree and its inlined tests

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

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

// Rays that a slightly different triangle test would answer differently: through vertices and
// edge midpoints (shared by two triangles), in a triangle's plane, stopping exactly at a hit,
// starting on a triangle, along an axis (zero direction components), and broken ones (NaN,
// zero direction, infinite origin).
std::vector<Ray> adversarial_rays(const Mesh& mesh) {
  std::vector<Ray> rays;
  std::mt19937 random(11);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  const auto triangle_count = static_cast<std::uint32_t>(mesh.boxes.size());
  for (int r = 0; r < 400; ++r) {
    const std::uint32_t t = static_cast<std::uint32_t>(random() % triangle_count);
    const glm::vec3 p0 = mesh.corner(t, 0), p1 = mesh.corner(t, 1), p2 = mesh.corner(t, 2);
    const glm::vec3 outside = glm::normalize(glm::vec3(uniform(random), uniform(random), uniform(random))) * 3.0f;
    Ray ray;
    ray.origin = outside;
    switch (r % 8) {
      case 0: ray.direction = p0 - outside; break;                    // a vertex, not normalised
      case 1: ray.direction = 0.5f * (p0 + p1) - outside; break;      // an edge's midpoint
      case 2: ray.origin = p0 - (p1 - p0); ray.direction = p1 - p0; break;  // along an edge
      case 3: ray.origin = (p0 + p1 + p2) / 3.0f; ray.direction = glm::normalize(outside); break;  // from a triangle
      case 4: ray.direction = glm::vec3(0.0f, 0.0f, -1.0f); ray.origin = glm::vec3(p0.x, p0.y, 3.0f); break;
      case 5: ray.direction = (p0 + p1 + p2) / 3.0f - outside; break;  // then stopped exactly at its hit
      case 6: ray.direction = glm::vec3(std::numeric_limits<float>::quiet_NaN(), 1.0f, 0.0f); break;
      default: ray.direction = r % 16 == 7 ? glm::vec3(0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
               if (r % 16 != 7) ray.origin = glm::vec3(-std::numeric_limits<float>::infinity(), 0.0f, 0.0f);
    }
    rays.push_back(ray);
  }
  return rays;
}

std::string text_of(const std::optional<BvhHit>& hit) {
  if (!hit) return "no hit";
  return "t " + std::to_string(hit->t_hit) + " on " + std::to_string(hit->primitive);
}

TEST(ReferenceBvh, InlinedTriangleTestGivesTheStageCallsAnswersBitForBit) {
  // The reference's own tree over a scene's triangles (solutions/05c_wide_bvh/fast_tree.h)
  // holds the triangles (reference::TriangleEdges) and tests them inlined, and their columns in
  // leaf order, tested four (the 8-wide tree: eight) at a time; every answer, t and the
  // barycentrics handed back to the bit, and every count must be those of calling stage 03, for
  // the binary traversal, the 4-wide one (stage 05c) and the reference's 8-wide one, whose
  // leaves are whole subtrees of up to 8 triangles.
  const Mesh& mesh = large_mesh();
  const testkit::IndexedTriangles triangles{&mesh.triangles.positions, &mesh.triangles.indices, &intersect_ray_triangle};
  const PrimitiveIntersector by_calls = testkit::intersector_over(triangles);
  std::vector<reference::TriangleEdges> edges;
  for (std::uint32_t t = 0; t < mesh.boxes.size(); ++t)
    edges.push_back(reference::TriangleEdges::of(mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2)));
  reference::LeafTriangles inlined;
  inlined.triangles = edges.data();

  std::vector<Ray> rays = adversarial_rays(mesh);
  std::mt19937 random(3);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  for (int r = 0; r < 2000; ++r) {  // and ordinary ones, from inside and outside
    Ray ray;
    ray.origin = glm::vec3(uniform(random), uniform(random), uniform(random)) * (r % 2 ? 0.3f : 3.0f);
    ray.direction = glm::vec3(uniform(random), uniform(random), uniform(random));
    rays.push_back(ray);
  }
  int hits = 0, failures = 0;
  // Leaves of up to 9 triangles too: then a leaf is tested four, four and one (eight and one) at a time.
  for (const Bvh& bvh :
       {build_bvh(mesh.boxes, kLeafSize), build_bvh_sah(mesh.boxes, kLeafSize), build_bvh(mesh.boxes, 9)}) {
    const Bvh4 wide = collapse_bvh4(bvh);
    // The reference's 8-wide tree (solutions/05c_wide_bvh/wide8.h), where the CPU has AVX2.
#if RAYLAB_AVX2_COMPILES
    std::optional<reference::Bvh8> wide8;
    if (reference::eight_wide_tree_runs_here()) wide8 = reference::collapse_bvh8(bvh);
#else
    const bool wide8 = false;
#endif
    // In the tree's leaf order (here not the triangles' own order): positions, not primitives.
    const std::vector<float> columns = reference::triangle_columns(edges.data(), bvh.primitive_order);
    reference::LeafTriangles four_at_a_time = inlined;
    four_at_a_time.columns = reference::TriangleColumns::of(columns);
    for (std::size_t r = 0; r < rays.size() && failures < 5; ++r) {
      Ray ray = rays[r];
      if (r < 400 && r % 8 == 5) {  // stop exactly at the first hit: it must be excluded by all
        BvhTraversalStats ignored;
        if (const std::optional<BvhHit> first = intersect_bvh(bvh, ray, by_calls, false, ignored)) ray.t_max = first->t_hit;
      }
      for (bool any_hit : {false, true}) {
        std::optional<BvhHit> binary_answer;
        for (int width : {2, 4, 8}) {
          if (width == 8 && !wide8) continue;
          const auto trace = [&](const PrimitiveIntersector& intersector, BvhTraversalStats& stats) {
#if RAYLAB_AVX2_COMPILES
            if (width == 8) return reference::intersect_bvh8(*wide8, ray, intersector, any_hit, stats);
#endif
            return width == 4 ? intersect_bvh4(wide, ray, intersector, any_hit, stats)
                              : intersect_bvh(bvh, ray, intersector, any_hit, stats);
          };
          const auto trace_inlined = [&](const reference::LeafTriangles& leaves, BvhTraversalStats& stats) {
#if RAYLAB_AVX2_COMPILES
            if (width == 8) return reference::intersect_bvh8_inlined(*wide8, ray, leaves, any_hit, stats);
#endif
            return width == 4 ? reference::intersect_bvh4_inlined(wide, ray, leaves, any_hit, stats)
                              : reference::intersect_bvh_inlined(bvh, ray, leaves, any_hit, stats);
          };
          BvhTraversalStats calls_stats;
          const std::optional<BvhHit> expected = trace(by_calls, calls_stats);
          hits += expected ? 1 : 0;
          if (width == 2) binary_answer = expected;
          // Every width finds the binary tree's closest t (an any-hit query: whether there is
          // one). Not always to the bit: where a ray meets a vertex, the triangles around it give
          // t's an ulp apart, and the trees, visiting leaves in other orders, may prune at a box
          // entry in between (a box whose float entry distance is an ulp beyond the hit).
          if (width != 2 && (expected.has_value() != binary_answer.has_value() ||
                             (expected && !any_hit &&
                              std::fabs(expected->t_hit - binary_answer->t_hit) > 4e-7f * binary_answer->t_hit))) {
            ++failures;
            ADD_FAILURE() << "ray " << r << " (" << ray << "), " << (any_hit ? "any" : "closest") << " hit: the "
                          << width << "-wide tree gives " << text_of(expected) << ", the binary tree "
                          << text_of(binary_answer);
          }
          for (const reference::LeafTriangles* leaves : {&inlined, &four_at_a_time}) {
            BvhTraversalStats stats;
            // The inlined tests also hand over the hit's details: those of stage 03's function
            // on the triangle returned, to the bit.
            TriangleHit details{std::nanf(""), std::nanf(""), std::nanf("")};
            reference::LeafTriangles with_details = *leaves;
            with_details.closest_triangle_hit = &details;
            const std::optional<BvhHit> got = trace_inlined(with_details, stats);
            std::optional<TriangleHit> stage_details;
            if (got)
              stage_details = intersect_ray_triangle(ray, mesh.corner(got->primitive, 0), mesh.corner(got->primitive, 1),
                                                     mesh.corner(got->primitive, 2));
            const bool same = got.has_value() == expected.has_value() &&
                              (!got || (std::memcmp(&got->t_hit, &expected->t_hit, sizeof(float)) == 0 &&
                                        got->primitive == expected->primitive && stage_details &&
                                        std::memcmp(&details, &*stage_details, sizeof(TriangleHit)) == 0));
            const bool same_work = calls_stats.nodes_visited == stats.nodes_visited &&
                                   calls_stats.primitives_tested == stats.primitives_tested;
            if (!same || !same_work) {
              ++failures;
              ADD_FAILURE() << "ray " << r << " (" << ray << "), " << (any_hit ? "any" : "closest") << " hit, "
                            << width << "-wide tree: "
                            << (leaves == &inlined ? "inlined " : "four at a time ") << text_of(got) << " after "
                            << stats.nodes_visited << " nodes and " << stats.primitives_tested
                            << " triangles; by calls " << text_of(expected) << " after " << calls_stats.nodes_visited
                            << " nodes and " << calls_stats.primitives_tested << " triangles";
            }
          }
        }
      }
    }
  }
  // The comparison proves little unless many rays hit: most of the ordinary ones do.
  EXPECT_GT(hits, 6000) << "queries that hit (3 trees, 2 or 3 widths, 2 queries per ray)";
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

namespace raylab {
namespace {

// The reference KD-tree (solutions/05d_kdtree) on a ray that lies in a split plane (z = 0.5): both
// sides are walked over the same interval, and inside the side walked first a plane across the
// ray (x = 5) pushes a cell above the other side on the stack. The side walked first has a hit
// inside its cell at t = 4; the other side holds a nearer one, B at t = 2, whose box starts at the
// plane (min z = 0.5: above only). A walk that stops at the first hit inside its cell returns 4.
TEST(ReferenceKdTree, ARayInASplitPlaneWalksBothSidesBeforeItStops) {
  TriangleMesh mesh;
  mesh.positions = {{4, -1, 0}, {4, 1, 0}, {4, 0, 1},            // A: across the plane, hit at x = 4
                    {2, -1, 0.5f}, {2, 1, 0.5f}, {2, 0, 1.5f},   // B: above the plane, hit at x = 2 (its edge)
                    {8, -1, 0}, {8, 1, 0}, {8, 0, 1}};           // C: far, below x = 5's plane
  mesh.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  KdTree tree;
  tree.bounds = Bounds3{glm::vec3(2, -1, 0), glm::vec3(8, 1, 1.5f)};
  tree.nodes.resize(5);
  tree.nodes[0].split_axis = 2, tree.nodes[0].split_position = 0.5f, tree.nodes[0].first_index = 1;
  tree.nodes[1].split_axis = 0, tree.nodes[1].split_position = 5.0f, tree.nodes[1].first_index = 3;
  tree.primitive_indices = {1, 0, 0, 2};  // above: B and A; below, x < 5: A; below, x > 5: C
  const auto leaf = [&](std::uint32_t node, std::uint32_t first, std::uint32_t count) {
    tree.nodes[node].leaf = 1, tree.nodes[node].first_index = first, tree.nodes[node].primitive_count = count;
  };
  leaf(2, 0, 2);
  leaf(3, 2, 1);
  leaf(4, 3, 1);
  const testkit::IndexedTriangles triangles{&mesh.positions, &mesh.indices, &intersect_ray_triangle};
  const PrimitiveIntersector intersector = testkit::intersector_over(triangles);
  Ray ray;
  ray.origin = glm::vec3(0.0f, 0.0f, 0.5f);
  ray.direction = glm::vec3(1.0f, 0.0f, 0.0f);
  const std::optional<BvhHit> expected = testkit::brute_force_hit(intersector, 3, ray);
  ASSERT_TRUE(expected.has_value());
  ASSERT_EQ(expected->t_hit, 2.0f);  // (B's edge counts as a hit)
  BvhTraversalStats stats;
  const std::optional<BvhHit> got = intersect_kdtree(tree, ray, intersector, false, stats);
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->t_hit, 2.0f);
  EXPECT_EQ(got->primitive, 1u);
}

}  // namespace
}  // namespace raylab
