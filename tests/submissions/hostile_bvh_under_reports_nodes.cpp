// Grader self-test submission (stage 05_bvh), hostile: a traversal that does too much work and
// hides it. It tests the box of EVERY node (it never skips a subtree; nearer child first, a
// leaf's triangles only when the ray enters its box before the closest hit so far), so its
// hits are right and its triangle tests few, but it reports one node visited per ray. Its
// honest count (all 2047 nodes of the bunny's tree) loses DoesNoMoreWorkThanTheReference; the
// lie must lose it too: the grader knows the nodes above the leaves it saw tested.
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
    const bool entered = intersect_ray_box(search, inverse, node.bounds).has_value();  // counted by nobody
    if (!node.is_leaf()) {
      const bool second_is_near = std::signbit(ray.direction[node.split_axis % 3]);
      stack[stack_size++] = node.first_index + (second_is_near ? 0u : 1u);  // far child waits
      stack[stack_size++] = node.first_index + (second_is_near ? 1u : 0u);
      continue;
    }
    if (!entered) continue;
    for (std::uint32_t i = node.first_index; i < node.first_index + node.primitive_count; ++i) {
      ++stats.primitives_tested;
      const std::uint32_t primitive = bvh.primitive_order[i];
      if (const auto t = intersector.test(intersector.context, search, primitive)) {
        search.t_max = *t;
        closest = BvhHit{*t, primitive};
        if (any_hit) return closest;
      }
    }
  }
  stats.nodes_visited += 1;  // the lie
  return closest;
}

}  // namespace raylab
