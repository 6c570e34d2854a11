// Grader self-test submission (stage 05_bvh): the reference builders with a broken
// traversal: tests every leaf: boxes are never used to skip a child (correct hits, far too much work)
// The reference file is included with its intersect_bvh renamed, so only the traversal differs.
#define intersect_bvh reference_intersect_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef intersect_bvh

namespace raylab {

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats);

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  const glm::vec3 inverse = ray_direction_inverse_of(ray);
  Ray search = ray;
  std::optional<BvhHit> closest;
  std::uint32_t stack[kBvhMaxDepth];
  int stack_size = 0;
  stack[stack_size++] = 0;
  while (stack_size > 0) {
    const BvhNode& node = bvh.nodes[stack[--stack_size]];
    ++stats.nodes_visited;
    if (!node.is_leaf()) {
      stack[stack_size++] = node.first_index + 1;
      stack[stack_size++] = node.first_index;
      continue;
    }
    for (std::uint32_t i = node.first_index; i < node.first_index + node.primitive_count; ++i) {
      ++stats.primitives_tested;
      const std::uint32_t primitive = bvh.primitive_order[i];
      if (const auto t = intersector.test(intersector.context, search, primitive)) {
        search.t_max = *t;
        closest = BvhHit{*t, primitive};
        if (any_hit) return closest;
      }
    }
    (void)inverse;
  }
  return closest;
}

}  // namespace raylab
