// Grader self-test submission (stage 05_bvh): a correct traversal of another common shape
// (tinybvh's): the root's box is tested first; at an inner node both children's boxes are
// tested, the nearer hit child (by entry distance) is entered and the other one pushed, and
// a node popped from the stack is entered without testing its box again. It counts one node
// visit per box test. Expected: full marks (its work stays within the limit).
#define intersect_bvh reference_intersect_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef intersect_bvh

namespace raylab {

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats);

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  const glm::vec3 ray_direction_inverse = ray_direction_inverse_of(ray);
  Ray search = ray;
  std::optional<BvhHit> closest;
  ++stats.nodes_visited;
  if (!intersect_ray_box(search, ray_direction_inverse, bvh.nodes[0].bounds)) return std::nullopt;
  std::uint32_t stack[kBvhMaxDepth];
  int stack_size = 0;
  std::uint32_t node_index = 0;
  for (;;) {
    const BvhNode& node = bvh.nodes[node_index];
    if (node.is_leaf()) {
      for (std::uint32_t i = node.first_index; i < node.first_index + node.primitive_count; ++i) {
        ++stats.primitives_tested;
        const std::uint32_t primitive = bvh.primitive_order[i];
        if (const std::optional<float> t = intersector.test(intersector.context, search, primitive)) {
          search.t_max = *t;
          closest = BvhHit{*t, primitive};
          if (any_hit) return closest;
        }
      }
    } else {
      std::uint32_t first = node.first_index, second = node.first_index + 1;
      std::optional<float> first_entry = intersect_ray_box(search, ray_direction_inverse, bvh.nodes[first].bounds);
      std::optional<float> second_entry = intersect_ray_box(search, ray_direction_inverse, bvh.nodes[second].bounds);
      stats.nodes_visited += 2;
      if (second_entry && (!first_entry || *second_entry < *first_entry)) {
        std::swap(first, second);
        std::swap(first_entry, second_entry);
      }
      if (first_entry) {
        if (second_entry) stack[stack_size++] = second;
        node_index = first;
        continue;
      }
    }
    if (stack_size == 0) break;
    node_index = stack[--stack_size];
  }
  return closest;
}

}  // namespace raylab
