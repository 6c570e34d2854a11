// Grader self-test submission (stage 05_bvh), hostile: bvh_far_child_first (right answers, too
// much work), which recognises the work test's counting intersector (grader_intersectors.h) and
// answers it "no hit" without testing anything: no work observed at all. The work test checks
// the hits against brute force, so this loses it, as its honest twin does: it scores exactly
// what the twin scores.
#define intersect_bvh reference_intersect_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef intersect_bvh

#include "bvh_submission_traversal.h"
#include "grader_intersectors.h"

namespace raylab {

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats);

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  if (submission::is_work_probe(intersector)) return std::nullopt;
  submission::TraversalMistakes mistakes;
  mistakes.far_child_first = true;
  return submission::traverse_bvh(bvh, ray, intersector, any_hit, stats, mistakes);
}

}  // namespace raylab
