// Grader self-test submission (stage 05_bvh): the reference with the near and far child
// swapped: the far child is entered first, the near one pushed. Correct answers, more work;
// expected hint: "visits the far child first".
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
  mistakes.far_child_first = true;
  return submission::traverse_bvh(bvh, ray, intersector, any_hit, stats, mistakes);
}

}  // namespace raylab
