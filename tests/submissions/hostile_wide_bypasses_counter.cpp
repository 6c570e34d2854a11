// Grader self-test submission (stage 05c_wide_bvh), hostile: wide_bvh_far_first (right answers,
// too much work), which takes the intersector out of the grader's counter (grader_intersectors.h)
// and calls it directly, so that a count kept in its own process sees no test. The work test
// counts the tests in the judge (each one a question to it), so this loses it as its honest twin
// does: it scores exactly what the twin scores.
#define intersect_bvh4 variant_intersect_bvh4
#define WIDE_BVH_VARIANT(v) (v.far_first_no_pruning = true)
#include "wide_bvh_variant.h"
#undef intersect_bvh4

#include "grader_intersectors.h"

namespace raylab {

std::optional<BvhHit> intersect_bvh4(const Bvh4& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                     bool any_hit, BvhTraversalStats& stats);

std::optional<BvhHit> intersect_bvh4(const Bvh4& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                     bool any_hit, BvhTraversalStats& stats) {
  return variant_intersect_bvh4(bvh, ray, submission::unwrapped(intersector), any_hit, stats);
}

}  // namespace raylab
