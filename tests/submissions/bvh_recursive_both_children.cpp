// Grader self-test submission (stage 05_bvh): the reference builders with the recursive
// traversal exactly as the course's pseudocode writes it: if the ray misses the node's box,
// no hit; in a leaf, the closest of its primitives; otherwise intersect both children (first,
// then second) and return the closer hit. Every call gets the ORIGINAL ray, so t_max is never
// lowered: the answers are right, the work is not (the second child is searched in full even
// when the first held a hit in front of it). Expected: full marks for the answers and the
// picture, and the work test names "t_max not lowered after a hit".
#define intersect_bvh reference_intersect_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef intersect_bvh

namespace raylab {

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats);

namespace {

std::optional<BvhHit> closer(const std::optional<BvhHit>& a, const std::optional<BvhHit>& b) {
  if (!a) return b;
  if (!b) return a;
  return b->t_hit < a->t_hit ? b : a;
}

std::optional<BvhHit> intersect_node(const Bvh& bvh, std::uint32_t node_index, const Ray& ray,
                                     const glm::vec3& ray_direction_inverse, const PrimitiveIntersector& intersector,
                                     bool any_hit, BvhTraversalStats& stats) {
  const BvhNode& node = bvh.nodes[node_index];
  ++stats.nodes_visited;
  if (!intersect_ray_box(ray, ray_direction_inverse, node.bounds)) return std::nullopt;
  if (node.is_leaf()) {
    std::optional<BvhHit> closest;
    for (std::uint32_t i = node.first_index; i < node.first_index + node.primitive_count; ++i) {
      ++stats.primitives_tested;
      const std::uint32_t primitive = bvh.primitive_order[i];
      if (const std::optional<float> t = intersector.test(intersector.context, ray, primitive)) {
        closest = closer(closest, BvhHit{*t, primitive});
        if (any_hit) break;
      }
    }
    return closest;
  }
  const std::optional<BvhHit> first =
      intersect_node(bvh, node.first_index, ray, ray_direction_inverse, intersector, any_hit, stats);
  if (any_hit && first) return first;
  const std::optional<BvhHit> second =
      intersect_node(bvh, node.first_index + 1, ray, ray_direction_inverse, intersector, any_hit, stats);
  return closer(first, second);
}

}  // namespace

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  return intersect_node(bvh, 0, ray, ray_direction_inverse_of(ray), intersector, any_hit, stats);
}

}  // namespace raylab
