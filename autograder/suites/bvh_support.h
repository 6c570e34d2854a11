// Test meshes and a brute-force oracle for the BVH suites (05_bvh, 05b_bvh_sah).
#pragma once

#include "support.h"

#include "raylab/bvh_tools.h"
#include "raylab/stages/05_bvh.h"

#include <array>
#include <string>
#include <vector>

namespace raylab::grading {

struct TestMesh {
  Message name;  // "the bunny", in either language
  std::vector<std::array<glm::vec3, 3>> triangles;
  std::vector<Bounds3> bounds;  // one per triangle, for the builders
};

// The meshes every BVH test runs on: the bunny (scenes/bunny.obj), a seeded triangle soup,
// a flat grid in the plane y = 0 (boxes of zero thickness), 64 copies of one triangle
// (every centroid equal: the median split must still terminate), and 100 overlapping
// triangles (the SAH prefers one leaf of them all, larger than max_leaf_size).
const std::vector<TestMesh>& bvh_test_meshes();
// A mesh of these triangles, with their boxes.
TestMesh make_test_mesh(Message name, std::vector<std::array<glm::vec3, 3>> triangles);

// The grader's own triangle test (double precision), so that BVH grades do not depend on
// your stage 3. A PrimitiveIntersector over a TestMesh.
PrimitiveIntersector intersector_for(const TestMesh& mesh);

// The mesh of the work tests (05 and 05c): the bunny turned, scaled and moved by amounts drawn
// once per run of the judge from a seed no stage server sees (std::random_device). A traversal
// has never been sent its triangles, so it can find its hits only by calling the intersector
// it is given, and every such call comes back to the judge, which counts it.
const TestMesh& work_test_mesh();

// Every triangle, t_max shrinking: the oracle.
std::optional<BvhHit> brute_force_closest(const TestMesh& mesh, const Ray& ray);

// Seeded rays at the mesh: origins on a sphere around it, aimed at points inside its box;
// with axis_aligned, directions along +-x, +-y or +-z (two zero components each).
std::vector<Ray> rays_at(const TestMesh& mesh, int count, std::uint32_t seed, bool axis_aligned = false);

// Primitives below each node (counted through the tree).
std::vector<std::uint32_t> subtree_primitive_counts(const Bvh& bvh);

// The work of a closest-hit traversal over `rays`, seen from the primitive test's side (the
// grader's own intersector counts every call) and from the traversal's own stats. Needs a
// tree that passes bvh_invariant_violation.
struct TraversalWork {
  std::uint64_t rays = 0;
  std::uint64_t nodes_visited = 0;         // the traversal's stats.nodes_visited
  std::uint64_t primitives_counted = 0;    // the traversal's stats.primitives_tested
  std::uint64_t primitives_tested = 0;     // calls of intersector.test, counted by the grader
  std::uint64_t nodes_implied = 0;         // nodes on the paths from the root to the leaves tested: the
                                           // fewest a top-down traversal can visit, counted by the grader
  std::uint64_t rays_nodes_under_reported = 0;  // rays whose stats.nodes_visited is below nodes_implied
  std::uint64_t calls_beyond_a_hit = 0;    // calls whose t_max is larger than a hit already reported for that ray
  std::uint64_t rays_beyond_a_hit = 0;     // rays with at least one such call
  std::uint64_t calls_after_a_hit = 0;     // calls after a hit was reported for that ray (any_hit must stop)
  std::uint64_t rays_after_a_hit = 0;      // rays with at least one such call
  std::uint64_t leaves_entered = 0;        // distinct leaves whose primitives were tested
  std::uint64_t leaves_missed_by_ray = 0;  // ... whose box the ray misses altogether
  std::uint64_t leaves_beyond_hit = 0;     // ... whose box the ray enters beyond a hit already reported
  std::uint64_t near_child_first = 0;      // inner nodes with leaves tested under both children: nearer one first
  std::uint64_t far_child_first = 0;       // ... the farther one first
  std::uint64_t rays_answered_wrong = 0;   // rays whose hit is not brute force's (the work of a
                                           // traversal that does not find its hits counts for nothing)
  double nodes_per_ray() const { return rays ? double(nodes_visited) / double(rays) : 0.0; }
  double nodes_implied_per_ray() const { return rays ? double(nodes_implied) / double(rays) : 0.0; }
  double tests_per_ray() const { return rays ? double(primitives_tested) / double(rays) : 0.0; }
};

// The grader's own median-split tree (the contract's build, ties broken by index), so that
// the traversal's work is judged whatever your build_bvh returns.
Bvh grader_median_tree(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size);

// The student's intersect_bvh on `rays` (closest hit), its hits checked against brute force.
// With any_hit, a ray is answered right when it has a hit exactly when brute force has one.
TraversalWork student_traversal_work(const Bvh& bvh, const TestMesh& mesh, const std::vector<Ray>& rays,
                                     bool any_hit = false);
// The grader's own traversal (the reference's algorithm: near child first, boxes tested with
// t_max lowered to the closest hit so far) with the stage server's box test (the one your
// intersect_bvh calls: the grader's own at stage 05) on the same tree and rays.
TraversalWork reference_traversal_work(const Bvh& bvh, const TestMesh& mesh, const std::vector<Ray>& rays);

// The triangle tests a traversal asks for after one of them hit (any_hit must stop there).
struct TestsAfterAHit {
  PrimitiveIntersector inner;
  bool hit = false;
  std::uint64_t calls = 0;
  static std::optional<float> test(void* context, const Ray& ray, std::uint32_t primitive) {
    TestsAfterAHit& self = *static_cast<TestsAfterAHit*>(context);
    if (self.hit) ++self.calls;
    const std::optional<float> t = self.inner.test(self.inner.context, ray, primitive);
    self.hit = self.hit || t.has_value();
    return t;
  }
};

// Index arithmetic on a student's tree without wrap-around: whether nodes[first_index] and
// nodes[first_index + 1] both exist.
inline bool children_in_range(const Bvh& bvh, const BvhNode& node) {
  return std::uint64_t(node.first_index) + 1 < bvh.nodes.size();
}

// Compares intersect_bvh with the oracle on `rays`; reports up to 3 differences with hints.
// Returns the number of rays that differ.
int compare_with_brute_force(const Bvh& bvh, const TestMesh& mesh, const std::vector<Ray>& rays, bool any_hit,
                             const Message& what);
// The same for any traversal's answers, one per ray. With graders_box_test, the traversal ran
// the grader's own box test, so a hit it loses is the traversal's doing (the hint says so).
int compare_traversal_with_brute_force(const std::vector<std::optional<BvhHit>>& answers, bool graders_box_test,
                                       const TestMesh& mesh, const std::vector<Ray>& rays, bool any_hit,
                                       const Message& what);

}  // namespace raylab::grading
