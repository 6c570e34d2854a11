// Stage 05_bvh: a bounding volume hierarchy (BVH).                       Handout: docs/05_bvh.md
//
// Without a BVH every ray tests every triangle: the camera rays alone of the bunny (3674
// triangles) at 1280x960 make 4.5 billion triangle tests. With one, a ray tests a dozen or two
// boxes and a handful of triangles. Three functions: build_bvh (the median split),
// intersect_bvh (the traversal) and, for the bonus stage 05b_bvh_sah, build_bvh_sah. Until
// build_bvh and intersect_bvh work, the renderer prints one line and tests every primitive
// (correct, just slow).
//
// THE DATA (raylab/stages/05_bvh.h; read it first)
//   Bvh::nodes            one flat array of 32-byte BvhNodes; nodes[0] is the root
//   BvhNode::bounds       a box holding every primitive below the node
//   inner node            primitive_count == 0; children are nodes[first_index] and
//                         nodes[first_index + 1]; the FIRST child holds the primitives with the
//                         smaller centroids along split_axis
//   leaf                  primitive_count = n > 0; its primitives are
//                         primitive_order[first_index .. first_index + n - 1]
//   Bvh::primitive_order  the primitive indices 0 .. N-1, each once, reordered so that each
//                         leaf's are contiguous
//
// ---------------------------------------------------------------------------------------------
// build_bvh(primitive_bounds, max_leaf_size)
//
// WHAT YOU RECEIVE
//   primitive_bounds   one box per primitive (triangle, sphere, or a whole mesh): primitive i
//                      is primitive_bounds[i]. You never see the primitives themselves.
//   max_leaf_size      the most primitives a leaf may hold (the renderer uses 4)
//
// WHAT YOU RETURN
//   A Bvh over all the primitives (empty nodes and primitive_order if there are none) in which
//   every leaf holds at most max_leaf_size primitives and only a node holding more than
//   max_leaf_size is split: along the longest axis of its bounds, at the median of its
//   primitives' centroids (the first child gets the smaller half, by count). Find the median
//   with your select_kth (stage 04b_quickselect, raylab/stages/04b_quickselect.h): its items are
//   the node's part of primitive_order, and its order compares two primitives' centroids along
//   the axis. Throw std::invalid_argument if max_leaf_size is outside 1 .. kBvhMaxLeafSize.
//
// READ docs/05_bvh.md, section 2 (the build step by step).
//
// ---------------------------------------------------------------------------------------------
// intersect_bvh(bvh, ray, intersector, any_hit, stats)
//
// WHAT YOU RECEIVE
//   bvh            a tree from build_bvh or build_bvh_sah (nodes may be empty: then no hit)
//   ray            the query: hits count for ray.t_min < t < ray.t_max
//   intersector    tests one primitive: intersector.test(intersector.context, ray, primitive)
//                  returns its t if hit inside (ray.t_min, ray.t_max), else std::nullopt.
//                  `primitive` is a value of bvh.primitive_order.
//   any_hit        false: find the CLOSEST hit. true (shadow rays): any hit will do -- return
//                  the first one you find, at once.
//   stats          add 1 to stats.nodes_visited for each node whose box you test, and 1 to
//                  stats.primitives_tested for each call of intersector.test
//
// WHAT YOU RETURN
//   BvhHit{t_hit, primitive} of the closest hit (or the first, for any_hit); std::nullopt if
//   nothing is hit. The work counts too (the autograder counts the triangles you test and the
//   leaves you enter, and checks your stats): skip what lies beyond the closest hit found so
//   far, and visit the near child first. How, not graded (the autograder sees only the
//   triangles and leaves): test a node's box (stage 04) before anything below it, and keep the
//   nodes to visit on a stack of kBvhMaxDepth entries, with no recursion and no allocation.
//
// READ docs/05_bvh.md, section 3 (the traversal loop), and section 4 (how the renderer uses it).
//
// ---------------------------------------------------------------------------------------------
// build_bvh_sah(primitive_bounds, max_leaf_size)                BONUS, stage 05b_bvh_sah
//
//   Receives and returns what build_bvh does (the same tree rules, leaves of at most
//   max_leaf_size), but splits each node where the surface area heuristic (SAH) predicts the
//   least work, and makes a leaf where splitting would not pay. Its tree must be valid and its
//   bvh_sah_cost (raylab/bvh_tools.h) close to the reference's; binning the centroids is the
//   usual way to find the split (the handout's), and any way that reaches that cost passes.
//
// READ docs/05_bvh.md, section 5 (the cost, binning, the special cases).
//
// COMMON MISTAKES: docs/05_bvh.md, section 6; the autograder's hints name them.
//
// HOW TO CHECK
//   build/bin/autograder --stage 05_bvh (and --stage 05b_bvh_sah); then
//   build/bin/raylab render scenes/bunny.json -o bunny.png should take seconds, not minutes,
//   and print no "testing every primitive" line.
#include "raylab/error.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/04b_quickselect.h"
#include "raylab/stages/05_bvh.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace raylab {

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  (void)primitive_bounds;
  (void)max_leaf_size;
  // Delete the line below when you write the function.
  throw NotImplemented("build_bvh");
}

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray,
                                    const PrimitiveIntersector& intersector, bool any_hit,
                                    BvhTraversalStats& stats) {
  (void)bvh;
  (void)ray;
  (void)intersector;
  (void)any_hit;
  (void)stats;
  // Delete the line below when you write the function.
  throw NotImplemented("intersect_bvh");
}

Bvh build_bvh_sah(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  (void)primitive_bounds;
  (void)max_leaf_size;
  // Bonus (stage 05b_bvh_sah): do build_bvh first. Delete the line below when you are done.
  throw NotImplemented("build_bvh_sah");
}

}  // namespace raylab
