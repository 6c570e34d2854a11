// Grader self-test submission (stage 05_bvh): the reference traversal testing primitive
// `i` (the position in the leaf's range) instead of primitive_order[i]. With the reference
// box test: wrong and missed hits, also on axis-aligned rays, and the hint must blame the
// traversal, never the box test (stage 04_box), which is right.
// The reference file is included with its intersect_bvh renamed; the traversal is the shared
// one of bvh_submission_traversal.h with this submission's mistake.
#define intersect_bvh reference_intersect_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef intersect_bvh

#include "bvh_submission_traversal.h"

namespace raylab {

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats);

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  submission::TraversalMistakes mistakes;
  mistakes.leaf_position_as_primitive = true;
  return submission::traverse_bvh(bvh, ray, intersector, any_hit, stats, mistakes);
}

}  // namespace raylab
