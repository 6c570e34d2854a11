// Autograder suites for stage 05_bvh (20 points) and the bonus stage 05b_bvh_sah (10 points).
#include "05_bvh_calls.h"
#include "bvh_support.h"
#include "bvh_violation_text.h"
#include "grading.h"

#include "raylab/bvh_tools.h"
#include "raylab/math.h"
#include "raylab/stages/05_bvh.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <utility>

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
  // No primitives: an empty tree. A max_leaf_size above kBvhMaxLeafSize (primitive_count is 16
  // bits): std::invalid_argument (not 0 or less, which a builder without the check could split
  // forever).
  const Bvh empty = build({}, kLeafSize);
  if (!empty.nodes.empty() || !empty.primitive_order.empty()) {
    add_failure({MessageId::bvh_failure_empty_input,
                 {{"builder", builder_name}, {"nodes", std::to_string(empty.nodes.size())}}});
    add_hint(MessageId::bvh_empty_input);
  }
  bool thrown = false;
  try {
    (void)build(kProbeBoxes, kBvhMaxLeafSize + 1);
  } catch (const std::invalid_argument&) {
    thrown = true;
  }
  if (!thrown) {
    add_failure({MessageId::bvh_failure_leaf_size_accepted,
                 {{"builder", builder_name}, {"size", std::to_string(kBvhMaxLeafSize + 1)}}});
    add_hint({MessageId::bvh_leaf_size_not_checked, {{"largest", std::to_string(kBvhMaxLeafSize)}}});
  }
  bool hinted = false;
  for (const TestMesh& mesh : bvh_test_meshes()) {
    const Bvh bvh = build(mesh.bounds, kLeafSize);
    if (const std::optional<BvhViolation> broken = find_bvh_violation(bvh, mesh.bounds, kLeafSize)) {
      const Message violation = bvh_violation_message(*broken);
      if (!hinted) add_hint({MessageId::bvh_breaks_invariant, {{"violation", violation}}});  // each mesh's rule is below
      hinted = true;
      add_failure({MessageId::bvh_failure_invariant,
                   {{"builder", builder_name}, {"mesh", mesh.name}, {"triangles", std::to_string(mesh.bounds.size())},
                    {"leaf_size", std::to_string(kLeafSize)}, {"violation", violation}}});
    }
  }
}

void expect_same_hits_as_brute_force(Builder build, const char* builder_name, bool any_hit, bool axis_aligned,
                                     const Message& what) {
  int differences = 0, rays_tested = 0;
  std::uint32_t seed = 7000;
  for (const TestMesh& mesh : bvh_test_meshes()) {
    Bvh bvh = build(mesh.bounds, kLeafSize);
    if (find_bvh_violation(bvh, mesh.bounds, kLeafSize)) {
      // A broken tree costs BuildsAValidTree; a traversal of it could run off its arrays.
      // Here your intersect_bvh is tested on the grader's own tree instead.
      add_note({MessageId::note_bvh_tree_broken, {{"builder", builder_name}, {"mesh", mesh.name}}});
      bvh = grader_median_tree(mesh.bounds, kLeafSize);
    }
    std::vector<Ray> rays = rays_at(mesh, 500, seed++, axis_aligned);
    if (!axis_aligned) {
      // The ray's own interval: rays that end halfway to their first hit (nothing to find), and
      // rays that start just past it (the next hit, or none).
      for (std::size_t i = 0; i < 100; ++i)
        if (const std::optional<BvhHit> first = brute_force_closest(mesh, rays[i])) {
          Ray ends = rays[i], starts = rays[i];
          ends.t_max = 0.5f * first->t_hit;
          starts.t_min = first->t_hit * 1.001f + 1e-4f;
          rays.push_back(ends);
          rays.push_back(starts);
        }
    }
    differences += compare_with_brute_force(bvh, mesh, rays, any_hit, what);
    rays_tested += static_cast<int>(rays.size());
  }
  EXPECT_EQ(differences, 0)
      << failure_text({MessageId::bvh_failure_brute_force,
                 {{"differences", std::to_string(differences)}, {"rays", std::to_string(rays_tested)}}});
}

GRADED_TEST(kStage, Stage05Bvh, BuildsAValidTree, 4) { expect_valid_trees(build_bvh, "build_bvh"); }

// Whether `axis` is a longest axis of `box` (a tie between two axes makes both longest).
bool is_longest(const Bounds3& box, int axis) {
  const glm::vec3 extent = box.max - box.min;
  return extent[axis] >= std::max({extent.x, extent.y, extent.z});
}

// Every inner node below the root of a valid tree: a median split (children's counts within 1)
// along a longest axis, of its box or of its centroids' box (either is the contract's; a tie
// between two axes allows both).
void expect_median_splits_below_the_root(const Bvh& bvh, const std::vector<Bounds3>& bounds,
                                         const std::vector<std::uint32_t>& counts) {
  // Each node's centroid box, children before parents (they come after them in the array).
  std::vector<Bounds3> centroids(bvh.nodes.size());
  for (std::size_t i = bvh.nodes.size(); i-- > 0;) {
    const BvhNode& node = bvh.nodes[i];
    if (node.is_leaf()) {
      for (std::uint32_t k = node.first_index; k < node.first_index + node.primitive_count; ++k)
        centroids[i].extend(bounds[bvh.primitive_order[k]].centroid());
    } else {
      centroids[i].extend(centroids[node.first_index]);
      centroids[i].extend(centroids[node.first_index + 1]);
    }
  }
  std::uint64_t not_halves = 0, wrong_axis = 0;
  std::size_t first_not_halves = 0, first_wrong_axis = 0;
  for (std::size_t i = 1; i < bvh.nodes.size(); ++i) {
    const BvhNode& node = bvh.nodes[i];
    if (node.is_leaf()) continue;
    const long long left = counts[node.first_index], right = counts[node.first_index + 1];
    if (std::llabs(left - right) > 1 && not_halves++ == 0) first_not_halves = i;
    if (node.split_axis > 2 || (!is_longest(node.bounds, node.split_axis) && !is_longest(centroids[i], node.split_axis)))
      if (wrong_axis++ == 0) first_wrong_axis = i;
  }
  if (not_halves > 0) {
    const BvhNode& node = bvh.nodes[first_not_halves];
    add_hint(MessageId::bvh_not_median);
    add_failure({MessageId::bvh_failure_inner_not_halves,
                 {{"node", std::to_string(first_not_halves)}, {"count", std::to_string(counts[first_not_halves])},
                  {"left", std::to_string(counts[node.first_index])}, {"right", std::to_string(counts[node.first_index + 1])},
                  {"nodes", std::to_string(not_halves)}}});
  }
  if (wrong_axis > 0) {
    const BvhNode& node = bvh.nodes[first_wrong_axis];
    add_hint(MessageId::bvh_split_axis_not_longest);
    add_failure({MessageId::bvh_failure_inner_split_axis,
                 {{"node", std::to_string(first_wrong_axis)}, {"count", std::to_string(counts[first_wrong_axis])},
                  {"axis", std::to_string(int(node.split_axis))}, {"box", box_text(node.bounds)},
                  {"longest", std::to_string(node.bounds.longest_axis())}, {"nodes", std::to_string(wrong_axis)}}});
  }
}

GRADED_TEST(kStage, Stage05Bvh, MedianSplitOnTheLongestAxis, 2) {
  // The root of the bunny's tree splits its longest axis into halves of equal size (+-1).
  const TestMesh& bunny = bvh_test_meshes().front();
  const Bvh bvh = build_bvh(bunny.bounds, kLeafSize);
  const std::string triangles = std::to_string(bunny.bounds.size());
  ASSERT_GE(bvh.nodes.size(), 3u) << failure_text({MessageId::bvh_failure_too_few_nodes, {{"triangles", triangles}}});
  const BvhNode& root = bvh.nodes[0];
  ASSERT_FALSE(root.is_leaf()) << failure_text({MessageId::bvh_failure_root_leaf, {{"triangles", triangles}}});
  ASSERT_TRUE(children_in_range(bvh, root))
      << failure_text({MessageId::bvh_failure_root_children,
                        {{"first", std::to_string(root.first_index)}, {"second", std::to_string(std::uint64_t(root.first_index) + 1)},
                         {"nodes", std::to_string(bvh.nodes.size())}}});
  const std::vector<std::uint32_t> counts = subtree_primitive_counts(bvh);
  const long long left = counts[root.first_index], right = counts[root.first_index + 1];
  if (std::llabs(left - right) > 1)
    add_hint(MessageId::bvh_not_median);
  EXPECT_LE(std::llabs(left - right), 1)
      << failure_text({MessageId::bvh_failure_not_halves, {{"left", std::to_string(left)}, {"right", std::to_string(right)}}});
  Bounds3 centroids;
  for (const Bounds3& b : bunny.bounds) centroids.extend(b.centroid());
  const int longest_node = root.bounds.longest_axis();
  const bool root_axis_longest = root.split_axis < 3 && (is_longest(root.bounds, root.split_axis) ||
                                                         is_longest(centroids, root.split_axis));
  if (!root_axis_longest) add_hint(MessageId::bvh_split_axis_not_longest);
  EXPECT_TRUE(root_axis_longest)
      << failure_text({MessageId::bvh_failure_split_axis,
                 {{"axis", std::to_string(int(root.split_axis))}, {"box", box_text(root.bounds)},
                  {"longest", std::to_string(longest_node)}}});
  // Only a node holding more than max_leaf_size primitives is split: of the nodes reachable from
  // the root, no inner one holds kLeafSize or fewer. (Children come after their parent, as
  // BuildsAValidTree checks; a walk that follows only such links ends on any tree.)
  std::uint64_t split_small = 0;
  std::size_t first_small = 0;
  std::vector<std::size_t> stack{0};
  while (!stack.empty()) {
    const std::size_t index = stack.back();
    stack.pop_back();
    const BvhNode& node = bvh.nodes[index];
    if (node.is_leaf() || !children_in_range(bvh, node) || node.first_index <= index) continue;
    if (counts[index] <= static_cast<std::uint32_t>(kLeafSize) && split_small++ == 0) first_small = index;
    stack.push_back(node.first_index);
    stack.push_back(node.first_index + 1);
  }
  if (split_small > 0) {
    add_hint({MessageId::bvh_splits_small_nodes, {{"leaf_size", std::to_string(kLeafSize)}}});
    add_failure({MessageId::bvh_failure_small_node_split,
                 {{"node", std::to_string(first_small)}, {"count", std::to_string(counts[first_small])},
                  {"leaf_size", std::to_string(kLeafSize)}, {"nodes", std::to_string(split_small)}}});
  }
  // The root's first child holds the smaller centroids along split_axis (a traversal enters the
  // nearer child first by that order): the largest of its primitives' centroids is at most the
  // smallest of the second child's. Judged on a valid tree only.
  const int axis = root.split_axis;
  const auto centroid_range = [&](std::size_t top) {
    float low = kInfinity, high = -kInfinity;
    std::vector<std::size_t> below{top};
    while (!below.empty()) {
      const std::size_t index = below.back();
      below.pop_back();
      const BvhNode& node = bvh.nodes[index];
      if (node.is_leaf()) {
        for (std::uint32_t i = node.first_index; i < node.first_index + node.primitive_count && i < bvh.primitive_order.size(); ++i) {
          const std::uint32_t primitive = bvh.primitive_order[i];
          if (primitive >= bunny.bounds.size()) continue;
          const float c = bunny.bounds[primitive].centroid()[axis];
          low = std::min(low, c);
          high = std::max(high, c);
        }
      } else if (children_in_range(bvh, node) && node.first_index > index) {
        below.push_back(node.first_index);
        below.push_back(node.first_index + 1);
      }
    }
    return std::make_pair(low, high);
  };
  if (axis < 3 && !find_bvh_violation(bvh, bunny.bounds, kLeafSize)) {  // (a broken tree is BuildsAValidTree's)
    const float first_high = centroid_range(root.first_index).second, second_low = centroid_range(root.first_index + 1).first;
    if (first_high > second_low) {
      add_hint(MessageId::bvh_children_swapped);
      add_failure({MessageId::bvh_failure_children_order,
                   {{"axis", std::to_string(axis)}, {"first", stream_text(first_high)}, {"second", stream_text(second_low)}}});
    }
    expect_median_splits_below_the_root(bvh, bunny.bounds, counts);
  }
}

GRADED_TEST(kStage, Stage05Bvh, ClosestHitsMatchBruteForce, 5) {
  expect_same_hits_as_brute_force(build_bvh, "build_bvh", false, false, MessageId::bvh_what_closest_hit);
  // An empty tree (a scene without triangles) hits nothing, and is not read beyond its end.
  std::vector<std::optional<BvhHit>> answers;
  {
    const HintIfLost hint(MessageId::bvh_empty_tree_read);
    answers = intersect_bvh_each(Bvh{}, {}, {make_ray(glm::vec3(0.0f), glm::vec3(0, 0, 1))}, false);
  }
  if (!answers.empty() && answers[0]) {
    add_hint(MessageId::bvh_empty_tree_read);
    add_failure({MessageId::bvh_failure_empty_tree_hit, {}});
  }
}

GRADED_TEST(kStage, Stage05Bvh, AnyHitAgreesWithBruteForce, 2) {
  expect_same_hits_as_brute_force(build_bvh, "build_bvh", true, false, MessageId::bvh_what_any_hit);
  // And it returns at once: after the first hit the intersector reports, no more tests (on the
  // grader's tree, through the intersector the judge answers).
  const TestMesh& bunny = work_test_mesh();
  const std::vector<Ray> rays = rays_at(bunny, 20, 98);  // few: each test is a call into the judge
  const TraversalWork work = student_traversal_work(grader_median_tree(bunny.bounds, kLeafSize), bunny, rays, true);
  if (work.rays_after_a_hit > 0)
    add_failure({MessageId::bvh_failure_any_hit_goes_on,
                 {{"rays", std::to_string(work.rays_after_a_hit)},
                  {"total", std::to_string(rays.size())},
                  {"calls", std::to_string(work.calls_after_a_hit)}}});
}

GRADED_TEST(kStage, Stage05Bvh, AxisAlignedRaysFindTheirHits, 2) {
  expect_same_hits_as_brute_force(build_bvh, "build_bvh", false, true, MessageId::bvh_what_closest_hit_axis_aligned);
}

// The work limits, against the grader's traversal of the same tree with the same rays (the
// reference's algorithm with the same box test as yours, the grader's own): any sound traversal
// stays well within them.
constexpr double kWorkMargin = 1.25;

std::string per_ray(double value) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << value;
  return text.str();
}

GRADED_TEST(kStage, Stage05Bvh, DoesNoMoreWorkThanTheReference, 3) {
  // Work is counted, never timed, and only what the grader observes itself is scored: the
  // triangles tested (every call of the intersector comes back to the grader) and the nodes on
  // the paths from the root to the leaves whose triangles were tested, per ray on the bunny,
  // your intersect_bvh against the grader's traversal, both on the grader's median-split tree
  // (so that only the traversal is judged here; your build_bvh has its own tests) with the same
  // rays. Your stats.nodes_visited is counted in your process: it is checked (never below what
  // the grader knows was visited) and compared for advice, but it never earns points
  // (docs/instructors.md, "Traversal work"). The bunny is turned and moved for this run
  // (work_test_mesh), so no triangle of it was ever sent to your process: your traversal finds its
  // hits only through the intersector it is given, and they must be brute force's.
  const TestMesh& bunny = work_test_mesh();
  const Bvh bvh = grader_median_tree(bunny.bounds, kLeafSize);
  std::vector<Ray> rays = rays_at(bunny, 1000, 99);
  // A traversal that tests nearly everything is judged on the first 10 rays: its verdict is
  // plain by then, and each of its tests is a call back into the grader (3,674 per ray on the
  // bunny), which on a loaded machine would spend the stage's time limit (it did, on 100).
  const std::vector<Ray> first_rays(rays.begin(), rays.begin() + 10);
  TraversalWork yours = student_traversal_work(bvh, bunny, first_rays);
  TraversalWork reference = reference_traversal_work(bvh, bunny, first_rays);
  if (yours.tests_per_ray() > 10 * reference.tests_per_ray() + 10) {
    rays = first_rays;
  } else {
    yours = student_traversal_work(bvh, bunny, rays);
    reference = reference_traversal_work(bvh, bunny, rays);
  }
  const double node_limit = kWorkMargin * reference.nodes_implied_per_ray() + 1.0;
  const double test_limit = kWorkMargin * reference.tests_per_ray() + 1.0;
  const double box_limit = kWorkMargin * reference.nodes_per_ray() + 1.0;  // advice only
  add_note({MessageId::note_bvh_work,
            {{"mesh", bunny.name}, {"triangles", std::to_string(bunny.bounds.size())},
             {"nodes", std::to_string(bvh.nodes.size())}, {"rays", std::to_string(rays.size())},
             {"your_nodes", per_ray(yours.nodes_implied_per_ray())},
             {"reference_nodes", per_ray(reference.nodes_implied_per_ray())}, {"node_limit", per_ray(node_limit)},
             {"your_tests", per_ray(yours.tests_per_ray())}, {"reference_tests", per_ray(reference.tests_per_ray())},
             {"test_limit", per_ray(test_limit)}, {"your_boxes", per_ray(yours.nodes_per_ray())},
             {"reference_boxes", per_ray(reference.nodes_per_ray())}}});

  if (yours.rays_answered_wrong > 0) {  // no work is no achievement when the answers are wrong
    add_failure({MessageId::work_failure_wrong_hits,
                 {{"wrong", gtest_text(yours.rays_answered_wrong)}, {"rays", gtest_text(rays.size())}, {"mesh", bunny.name}}});
    return;
  }
  const bool too_much = yours.nodes_implied_per_ray() > node_limit || yours.tests_per_ray() > test_limit;
  bool explained = false;
  if (yours.calls_beyond_a_hit > 0) {
    explained = true;
    add_hint({MessageId::bvh_t_max_not_lowered,
              {{"rays", std::to_string(yours.rays_beyond_a_hit)}, {"total", std::to_string(rays.size())},
               {"calls", std::to_string(yours.calls_beyond_a_hit)}}});
    add_failure({MessageId::bvh_failure_t_max,
                 {{"calls", gtest_text(yours.calls_beyond_a_hit)}, {"rays", gtest_text(yours.rays_beyond_a_hit)}}});
  }
  if (yours.leaves_missed_by_ray > 0) {
    explained = true;
    add_hint({MessageId::bvh_tests_missed_leaves,
              {{"missed", std::to_string(yours.leaves_missed_by_ray)}, {"entered", std::to_string(yours.leaves_entered)}}});
    add_failure({MessageId::bvh_failure_missed_leaves,
                 {{"missed", gtest_text(yours.leaves_missed_by_ray)}, {"entered", gtest_text(yours.leaves_entered)}}});
  }
  const std::uint64_t ordered = yours.near_child_first + yours.far_child_first;
  const double near_fraction = ordered ? double(yours.near_child_first) / double(ordered) : 1.0;
  if (too_much && yours.leaves_missed_by_ray == 0 && ordered > 0 && near_fraction < 0.75) {
    explained = true;
    if (near_fraction < 0.25)
      add_hint(MessageId::bvh_far_child_first);
    else
      add_hint({MessageId::bvh_near_child_sometimes, {{"percent", std::to_string(int(100 * near_fraction))}}});
  }
  if (too_much && !explained && yours.leaves_beyond_hit > reference.leaves_beyond_hit + yours.leaves_entered / 10) {
    explained = true;
    add_hint({MessageId::bvh_enters_beyond_hit,
              {{"beyond", std::to_string(yours.leaves_beyond_hit)}, {"entered", std::to_string(yours.leaves_entered)}}});
  }
  if (too_much && !explained)
    add_hint(MessageId::bvh_too_much_work);
  if (yours.primitives_counted != yours.primitives_tested) {
    add_hint(MessageId::bvh_stats_not_counted);
    add_failure({MessageId::bvh_failure_stats,
                 {{"counted", per_ray(double(yours.primitives_counted) / rays.size())},
                  {"tested", per_ray(yours.tests_per_ray())}}});
  }
  // Nodes visited are the one figure here that the grader takes from your process (your
  // traversal counts them in the stage server; docs/instructors.md): checked against the nodes
  // the grader knows were visited, those above the leaves whose triangles it saw tested.
  if (yours.rays_nodes_under_reported > 0) {
    add_hint(MessageId::bvh_nodes_not_counted);
    add_failure({MessageId::bvh_failure_nodes_under_reported,
                 {{"rays", gtest_text(yours.rays_nodes_under_reported)}, {"total", gtest_text(rays.size())}}});
  }
  // Box tests beyond those the grader sees cost time, not points: advice from your own count.
  if (!too_much && yours.rays_nodes_under_reported == 0 && yours.nodes_per_ray() > box_limit)
    add_hint({MessageId::bvh_unscored_box_tests,
              {{"yours", per_ray(yours.nodes_per_ray())}, {"reference", per_ray(reference.nodes_per_ray())}}});
  EXPECT_FALSE(too_much) << failure_text(MessageId::bvh_failure_too_much_work);
}

GRADED_TEST(kStage, Stage05Bvh, BunnyImageMatchesReference, 2) {
  expect_image_matches_reference(kStage, 0.05f, 0.005);
}

// Only build_bvh_sah is graded here: a tree that keeps every rule gives every closest hit to a
// sound traversal, and your traversal (intersect_bvh) is stage 05's to grade, not this stage's.
GRADED_TEST(kBonusStage, Stage05bBvhSah, BuildsAValidTree, 6) { expect_valid_trees(build_bvh_sah, "build_bvh_sah"); }

GRADED_TEST(kBonusStage, Stage05bBvhSah, SahCostNearTheReference, 4) {
  // The SAH cost (bvh_sah_cost: expected work of a ray that hits the root) of your tree for
  // the bunny, against the reference SAH tree's (checked in) and the median split's.
  const nlohmann::json data = load_reference_cases("05_bvh");
  const double reference_sah = data.at("bunny_sah_cost").get<double>();
  const double reference_median = data.at("bunny_median_cost").get<double>();
  const TestMesh& bunny = bvh_test_meshes().front();
  const Bvh tree = build_bvh_sah(bunny.bounds, kLeafSize);
  const double cost = bvh_sah_cost(tree);
  const double limit = reference_sah + 0.5 * (reference_median - reference_sah);
  const Message note{MessageId::note_bvh_sah_cost,
                     {{"cost", stream_text(cost)}, {"reference", stream_text(reference_sah)},
                      {"median", stream_text(reference_median)}, {"limit", stream_text(limit)}}};
  add_note(note);
  if (cost > limit)  // (the cost comes from the tree's boxes: a broken tree's says nothing of its splits)
    add_hint(find_bvh_violation(tree, bunny.bounds, kLeafSize) ? MessageId::bvh_sah_cost_of_broken_tree
                                                                : MessageId::bvh_sah_not_better);
  EXPECT_LE(cost, limit) << failure_text(note);
}

}  // namespace
}  // namespace raylab::grading
