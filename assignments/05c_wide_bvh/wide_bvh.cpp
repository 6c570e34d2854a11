// Stage 05c_wide_bvh (bonus): a 4-wide BVH with SIMD box tests.  Handout: docs/05c_wide_bvh.md
//
// A binary BVH tests two boxes per node and goes down one level at a time. A 4-wide BVH skips
// every other level: each node holds up to four children, whose boxes are stored coordinate by
// coordinate (min_x[4], min_y[4], ...), so that one SIMD instruction works on a coordinate of
// all four at once. CPUs since 1999 (SSE) compute four floats per instruction; Embree and
// every production ray tracer traverse such trees. You write three functions:
//
//   collapse_bvh4        your stage 05 binary tree -> a 4-wide tree with the same leaves
//   intersect_ray_box4   stage 04's slab test on the four children of a node at once
//   intersect_bvh4       stage 05's traversal, through the 4-wide tree
//
// WHAT YOU GET
//   Bvh4Node, Bvh4, empty_bvh4_node() (raylab/stages/05c_wide_bvh.h): the layout. Read the
//     comment above Bvh4Node: which slots are inner children, which leaves, which empty.
//   Bvh, BvhNode, PrimitiveIntersector, BvhTraversalStats, BvhHit, kBvhMaxDepth (stage 05).
//   ray_direction_inverse_of(ray) (stage 04); gamma_bound (raylab/math.h).
//   SIMD: #include <xmmintrin.h> gives SSE (__m128: four floats; _mm_set1_ps, _mm_loadu_ps,
//     _mm_sub_ps, _mm_mul_ps, _mm_min_ps, _mm_max_ps, _mm_cmple_ps, _mm_movemask_ps). A plain
//     loop over the four slots is correct too, and the autograder grades correctness and work,
//     not speed: start with the loop, then make it SIMD (handout section 4).
//
// THE RULES
//   - collapse_bvh4 keeps the binary tree's leaves (same primitive ranges, same boxes) and its
//     primitive_order; each wide node takes a binary inner node's two children and, while it
//     has fewer than 4 and one of them is an inner node, replaces such a child by its two
//     children (handout section 2 opens the one with the largest surface area first, which pays
//     best; the autograder checks the tree's rules and that it is wide, not the order). Empty
//     slots as empty_bvh4_node() makes them. The root is nodes[0]; a binary tree that is one leaf gives one wide node with that
//     leaf as its only child; an empty binary tree an empty Bvh4.
//   - intersect_ray_box4 follows stage 04's contract for every child: it never loses a hit
//     (zero direction components, the origin on a face plane, rounding), and sets no bit for
//     the empty slots (i >= child_count).
//   - intersect_bvh4 gives stage 05's answers; it visits the children nearest first (by entry
//     distance), skips what lies beyond the closest hit so far, stops at the first hit for
//     any_hit, and counts one node visited per intersect_ray_box4 call and one primitive per
//     intersector.test call.
//
// READ docs/05c_wide_bvh.md: section 1 (why wide), 2 (collapsing), 3 (the layout), 4 (four boxes
//   at once, with SSE), 5 (the traversal), 6 (common mistakes, which the autograder's hints
//   name, and how to check).
//
// HOW TO CHECK
//   build/bin/autograder --stage 05c_wide_bvh
#include "raylab/error.h"
#include "raylab/stages/05c_wide_bvh.h"

namespace raylab {

// RETURN the 4-wide tree of `binary` (handout section 2).
Bvh4 collapse_bvh4(const Bvh& binary) {
  (void)binary;
  // Delete the line below when you write the function (handout section 2).
  throw NotImplemented("collapse_bvh4");
}

// RETURN the mask of the children of `node` whose boxes the ray enters within [ray.t_min,
// ray.t_max] (bit i for slot i), and write each such child's entry distance, max(t_enter,
// ray.t_min), to entry_distances[i] (handout section 4).
unsigned intersect_ray_box4(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bvh4Node& node,
                            float entry_distances[kBvh4Width]) {
  (void)ray;
  (void)ray_direction_inverse;
  (void)node;
  (void)entry_distances;
  throw NotImplemented("intersect_ray_box4");
}

// RETURN the closest hit (any_hit false) or the first hit found (any_hit true) through the
// 4-wide tree, nullopt when nothing is hit; add the work to `stats` (handout section 5).
std::optional<BvhHit> intersect_bvh4(const Bvh4& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                     bool any_hit, BvhTraversalStats& stats) {
  (void)bvh;
  (void)ray;
  (void)intersector;
  (void)any_hit;
  (void)stats;
  throw NotImplemented("intersect_bvh4");
}

}  // namespace raylab
