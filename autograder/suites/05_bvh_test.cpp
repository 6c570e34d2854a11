// Autograder suites for stage 05_bvh (20 points) and the bonus stage 05b_bvh_sah (10 points).
#include "bvh_support.h"
#include "grading.h"

#include "raylab/stages/05_bvh.h"

#include <cmath>
#include <sstream>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "05_bvh";
constexpr const char* kBonusStage = "05b_bvh_sah";
constexpr int kLeafSize = 4;

const std::vector<Bounds3> kProbeBoxes{Bounds3{glm::vec3(0), glm::vec3(1)}, Bounds3{glm::vec3(2), glm::vec3(3)}};
const bool kRegistered = register_stage(kStage, [] { (void)build_bvh(kProbeBoxes, 1); });
const bool kBonusRegistered = register_stage(kBonusStage, [] { (void)build_bvh_sah(kProbeBoxes, 1); });

using Builder = Bvh (*)(const std::vector<Bounds3>&, int);

void expect_valid_trees(Builder build, const char* builder_name) {
  for (const TestMesh& mesh : bvh_test_meshes()) {
    const Bvh bvh = build(mesh.bounds, kLeafSize);
    const std::string violation = bvh_invariant_violation(bvh, mesh.bounds, kLeafSize);
    if (!violation.empty()) {
      add_hint("the tree breaks a rule every BVH keeps: " + violation);
      ADD_FAILURE() << builder_name << " on " << mesh.name << " (" << mesh.bounds.size() << " triangles, leaves of at most "
                    << kLeafSize << "): " << violation;
    }
  }
}

void expect_same_hits_as_brute_force(Builder build, bool any_hit, bool axis_aligned, const char* what) {
  int differences = 0, rays_tested = 0;
  std::uint32_t seed = 7000;
  for (const TestMesh& mesh : bvh_test_meshes()) {
    const Bvh bvh = build(mesh.bounds, kLeafSize);
    const std::vector<Ray> rays = rays_at(mesh, 500, seed++, axis_aligned);
    differences += compare_with_brute_force(bvh, mesh, rays, any_hit, what);
    rays_tested += static_cast<int>(rays.size());
  }
  EXPECT_EQ(differences, 0) << differences << " of " << rays_tested << " rays differ from testing every triangle";
}

GRADED_TEST(kStage, Stage05Bvh, BuildsAValidTree, 4) { expect_valid_trees(build_bvh, "build_bvh"); }

GRADED_TEST(kStage, Stage05Bvh, MedianSplitOnTheLongestAxis, 2) {
  // The root of the bunny's tree splits its longest axis into halves of equal size (+-1).
  const TestMesh& bunny = bvh_test_meshes().front();
  const Bvh bvh = build_bvh(bunny.bounds, kLeafSize);
  ASSERT_GE(bvh.nodes.size(), 3u) << "a tree over " << bunny.bounds.size() << " triangles needs more than a root";
  const BvhNode& root = bvh.nodes[0];
  ASSERT_FALSE(root.is_leaf()) << "the root of " << bunny.bounds.size() << " triangles must be split";
  ASSERT_LT(root.first_index + 1, bvh.nodes.size());
  const std::vector<std::uint32_t> counts = subtree_primitive_counts(bvh);
  const long long left = counts[root.first_index], right = counts[root.first_index + 1];
  if (std::llabs(left - right) > 1)
    add_hint("the split is not at the median: put half of the primitives (by centroid, std::nth_element) on each side");
  EXPECT_LE(std::llabs(left - right), 1) << "the root's children hold " << left << " and " << right << " triangles";
  Bounds3 centroids;
  for (const Bounds3& b : bunny.bounds) centroids.extend(b.centroid());
  const int longest_node = root.bounds.longest_axis(), longest_centroids = centroids.longest_axis();
  if (root.split_axis != longest_node && root.split_axis != longest_centroids)
    add_hint("the split axis is not the longest axis of the node's box");
  EXPECT_TRUE(root.split_axis == longest_node || root.split_axis == longest_centroids)
      << "root split_axis " << int(root.split_axis) << ", but the longest axis of its box " << root.bounds << " is "
      << longest_node;
}

GRADED_TEST(kStage, Stage05Bvh, ClosestHitsMatchBruteForce, 5) {
  expect_same_hits_as_brute_force(build_bvh, false, false, "closest hit");
}

GRADED_TEST(kStage, Stage05Bvh, AnyHitAgreesWithBruteForce, 2) {
  expect_same_hits_as_brute_force(build_bvh, true, false, "any hit");
}

GRADED_TEST(kStage, Stage05Bvh, AxisAlignedRaysFindTheirHits, 2) {
  expect_same_hits_as_brute_force(build_bvh, false, true, "closest hit, axis-aligned ray");
}

GRADED_TEST(kStage, Stage05Bvh, VisitsFarFewerNodesThanBruteForce, 3) {
  // Work is counted, never timed: nodes visited and triangles tested per ray on the bunny.
  // The reference visits about 1% of the triangles' count; the limits leave room for any
  // sound median-split tree and fail a traversal that does not prune.
  const TestMesh& bunny = bvh_test_meshes().front();
  const Bvh bvh = build_bvh(bunny.bounds, kLeafSize);
  const std::vector<Ray> rays = rays_at(bunny, 2000, 99);
  BvhTraversalStats stats;
  for (const Ray& ray : rays) (void)intersect_bvh(bvh, ray, intersector_for(bunny), false, stats);
  const double nodes_per_ray = double(stats.nodes_visited) / rays.size();
  const double tests_per_ray = double(stats.primitives_tested) / rays.size();
  const double triangles = double(bunny.bounds.size());
  std::ostringstream note;
  note << "per ray on the bunny (" << bunny.bounds.size() << " triangles): " << nodes_per_ray << " nodes visited (limit "
       << 0.05 * triangles << "), " << tests_per_ray << " triangles tested (limit " << 0.02 * triangles << ")";
  add_note(note.str());
  if (nodes_per_ray > 0.05 * triangles || tests_per_ray > 0.02 * triangles)
    add_hint("the traversal does too much work: skip a child whose box the ray misses or whose entry is beyond the "
             "closest hit so far, and visit the nearer child first so that the closest hit is found early");
  EXPECT_LE(nodes_per_ray, 0.05 * triangles) << note.str();
  EXPECT_LE(tests_per_ray, 0.02 * triangles) << note.str();
}

GRADED_TEST(kStage, Stage05Bvh, BunnyImageMatchesReference, 2) {
  expect_image_matches_reference(kStage, 0.05f, 0.005);
}

GRADED_TEST(kBonusStage, Stage05bBvhSah, BuildsAValidTree, 3) { expect_valid_trees(build_bvh_sah, "build_bvh_sah"); }

GRADED_TEST(kBonusStage, Stage05bBvhSah, ClosestHitsMatchBruteForce, 3) {
  expect_same_hits_as_brute_force(build_bvh_sah, false, false, "closest hit through the SAH tree");
}

GRADED_TEST(kBonusStage, Stage05bBvhSah, SahCostNearTheReference, 4) {
  // The SAH cost (bvh_sah_cost: expected work of a ray that hits the root) of your tree for
  // the bunny, against the reference SAH tree's (checked in) and the median split's.
  const nlohmann::json data = load_reference_cases("05_bvh");
  const double reference_sah = data.at("bunny_sah_cost").get<double>();
  const double reference_median = data.at("bunny_median_cost").get<double>();
  const TestMesh& bunny = bvh_test_meshes().front();
  const double cost = bvh_sah_cost(build_bvh_sah(bunny.bounds, kLeafSize));
  const double limit = reference_sah + 0.5 * (reference_median - reference_sah);
  std::ostringstream note;
  note << "SAH cost on the bunny: yours " << cost << ", reference SAH " << reference_sah << ", median split "
       << reference_median << " (limit " << limit << ", halfway between)";
  add_note(note.str());
  if (cost > limit)
    add_hint("the SAH tree is not much better than a median split: for each axis, bin the centroids, sweep the bins "
             "to evaluate cost = area(left) * count(left) + area(right) * count(right) at every boundary, take the "
             "cheapest, and make a leaf when no split is cheaper than testing every primitive");
  EXPECT_LE(cost, limit) << note.str();
}

}  // namespace
}  // namespace raylab::grading
