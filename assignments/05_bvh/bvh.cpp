// Stage 05_bvh: a bounding volume hierarchy (BVH).                       Handout: docs/05_bvh.md
//
// Without a BVH every ray tests every triangle: the camera rays alone of the bunny (3674
// triangles) at 1280x960 make 4.5 billion triangle tests. With one, a ray tests a dozen or two
// boxes and a handful of triangles. Three functions: build_bvh (the median split),
// intersect_bvh (the traversal) and, for the bonus stage 5b, build_bvh_sah. Until build_bvh
// and intersect_bvh work, the renderer prints one line and tests every primitive (correct,
// just slow).
//
// THE DATA (raylab/stages/05_bvh.h; read it first)
//   Bvh::nodes            one flat array of 32-byte BvhNodes; nodes[0] is the root
//   BvhNode::bounds       a box holding every primitive below the node
//   inner node            primitive_count == 0; children are nodes[first_index] and
//                         nodes[first_index + 1]; the FIRST child holds the primitives with the
//                         smaller centroids along split_axis
//   leaf                  primitive_count = n > 0; its primitives are
//                         primitive_order[first_index .. first_index + n - 1]
//   Bvh::primitive_order  the primitive indices 0 .. N-1, reordered so that each leaf's are
//                         contiguous
//
// ---------------------------------------------------------------------------------------------
// build_bvh(primitive_bounds, max_leaf_size)                       (docs/05_bvh.md, section 2)
//
// WHAT YOU RECEIVE
//   primitive_bounds   one box per primitive (triangle, sphere, or a whole mesh): primitive i
//                      is primitive_bounds[i]. You never see the primitives themselves.
//   max_leaf_size      the most primitives a leaf may hold (the renderer uses 4)
//
// WHAT YOU RETURN
//   A Bvh over all the primitives (empty nodes and primitive_order if there are none), built
//   top-down. For the node holding primitive_order[begin .. end):
//     1. its bounds = the union of its primitives' boxes;
//     2. if end - begin <= max_leaf_size: make it a leaf, done;
//     3. else split_axis = bounds.longest_axis(); put the median primitive in place with
//          std::nth_element(order + begin, order + middle, order + end, compare)
//        where middle = begin + (end - begin) / 2 and compare orders two primitives by their
//        box's centroid()[split_axis]. Now [begin, middle) has the smaller centroids;
//     4. append BOTH children to nodes at once (first_index = nodes.size() before appending),
//        then build the first child over [begin, middle), the second over [middle, end).
//   Fill primitive_order with 0 .. N-1 (std::iota) before you start. Throw
//   std::invalid_argument if max_leaf_size is outside 1 .. kBvhMaxLeafSize.
//
// COMMON MISTAKES
//   keeping a reference (BvhNode&) across nodes.push_back: the vector may move, the reference
//   dangles (use indices); sorting the whole range (std::sort works, but is O(n log n) per
//   level; nth_element is O(n)); a leaf's first_index pointing into nodes instead of
//   primitive_order; children not adjacent.
//
// ---------------------------------------------------------------------------------------------
// intersect_bvh(bvh, ray, intersector, any_hit, stats)             (docs/05_bvh.md, section 3)
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
//   nothing is hit.
//
// THE LOOP (section 3): no recursion, no allocation.
//   ray_direction_inverse = ray_direction_inverse_of(ray), ONCE, before the loop (stage 04).
//   Keep a copy of the ray, `search`, whose t_max you lower to each hit's t: then boxes and
//   primitives beyond the closest hit so far are skipped for free, and every hit that the
//   intersector reports is closer than the last.
//   A stack of node indices: std::uint32_t stack[kBvhMaxDepth] (the builders never go
//   deeper). Start at node 0. For each node:
//     - test its box: intersect_ray_box(search, ray_direction_inverse, node.bounds); on a miss
//       (or an entry beyond search.t_max, which the box test also reports as a miss) go on
//       with the node on top of the stack;
//     - a leaf: test each of its primitives with the intersector; on a hit lower search.t_max
//       and remember the hit (for any_hit: return it);
//     - an inner node: visit the NEAR child first. The first child is on the lower side of
//       split_axis, so it is nearer when the ray goes up that axis: if
//       ray_direction_inverse[split_axis] < 0 the second child is the near one. Push the far
//       child, continue with the near one.
//   Stop when the stack is empty.
//
// COMMON MISTAKES
//   not lowering t_max after a hit (returns the last hit found, not the closest); stopping at
//   the first hit when any_hit is false; a near/far order that is right but reversed (still
//   correct, just slow: compare stats.nodes_visited with the reference); recomputing
//   1 / direction for every box.
//
// ---------------------------------------------------------------------------------------------
// build_bvh_sah(primitive_bounds, max_leaf_size)       BONUS, stage 5b (docs/05_bvh.md, sec. 5)
//
//   Like build_bvh, but each node is split where the surface area heuristic (SAH) says a ray
//   will do the least work. The cost of a split into primitive sets L and R of a node N is
//     1 + (area(L) * count(L) + area(R) * count(R)) / area(N)
//   (area = Bounds3::surface_area of the set's union box), and a leaf costs count(N).
//   Binned: over the box of the primitives' CENTROIDS, cut each axis into 16 equal bins, drop
//   each primitive into its bin by centroid, then sweep the 15 planes between bins from both
//   ends (prefix unions and counts) to get every split's cost in O(bins). Take the cheapest
//   split over the three axes; make a leaf if that costs no less than a leaf and
//   count <= max_leaf_size. If all centroids coincide (no plane separates them), split at the
//   median as build_bvh does. Keep the depth below kBvhMaxDepth (e.g. switch to median splits
//   below depth 30). Check: bvh_sah_cost (05_bvh.h) of your tree is lower than build_bvh's.
//
// HOW TO CHECK
//   build/bin/autograder --stage 05_bvh; then build/bin/raylab render scenes/bunny.json -o bunny.png
//   should take seconds, not minutes, and print no "testing every primitive" line.
#include "raylab/error.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace raylab {

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  (void)primitive_bounds;
  (void)max_leaf_size;
  // Start with step 1 of build_bvh above. Delete the line below when you are done.
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
  // Start with ray_direction_inverse and the stack above. Delete the line below when done.
  throw NotImplemented("intersect_bvh");
}

Bvh build_bvh_sah(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  (void)primitive_bounds;
  (void)max_leaf_size;
  // Bonus (stage 5b): do build_bvh first. Delete the line below when you are done.
  throw NotImplemented("build_bvh_sah");
}

}  // namespace raylab
