// Grader self-test submission (stage 05_bvh), hostile: bvh_far_child_first (right answers, too
// much work), which keeps a copy of every mesh the grader's own triangle test is given in the
// earlier tests, and when the work test's counting intersector comes (grader_intersectors.h)
// traverses with the grader's triangle test on the kept mesh of the same size instead, counting
// none of those tests in its stats: right hits on a mesh it has seen, and no work observed. The work test's mesh is the bunny moved for
// each run, never sent to this process, so the hits are wrong and the work test is lost, as its
// honest twin loses it: it scores exactly what the twin scores.
#define intersect_bvh reference_intersect_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef intersect_bvh

#include "bvh_submission_traversal.h"
#include "grader_intersectors.h"

#include <array>
#include <map>
#include <vector>

namespace raylab {

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats);

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  using Mesh = std::vector<std::array<glm::vec3, 3>>;
  static std::map<std::size_t, Mesh> kept;  // by number of triangles
  const PrimitiveIntersector inner = submission::unwrapped(intersector);
  if (inner.test == &grading::grader_triangle_test) {
    const Mesh& mesh = *static_cast<const Mesh*>(inner.context);
    Mesh& copy = kept[mesh.size()];
    if (copy != mesh) copy = mesh;
  }
  submission::TraversalMistakes mistakes;
  mistakes.far_child_first = true;
  const auto found = kept.find(bvh.primitive_order.size());
  if (submission::is_work_probe(intersector) && found != kept.end()) {
    const PrimitiveIntersector own{&grading::grader_triangle_test, &found->second};
    mistakes.primitives_not_counted = true;  // stats agree with the tests the judge sees: none
    return submission::traverse_bvh(bvh, ray, own, any_hit, stats, mistakes);
  }
  return submission::traverse_bvh(bvh, ray, intersector, any_hit, stats, mistakes);
}

}  // namespace raylab
