// Grader self-test submission (stage 05_bvh): the reference with the near and far child
// swapped: the far child is entered first, the near one pushed. Correct answers, more work;
// expected hint: "visits the far child first".
#define intersect_bvh reference_intersect_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef intersect_bvh

namespace raylab {

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats);

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray,
                                    const PrimitiveIntersector& intersector, bool any_hit,
                                    BvhTraversalStats& stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  const glm::vec3 ray_direction_inverse = ray_direction_inverse_of(ray);
  // 1 / -0 = -infinity < 0: a -0 component counts as negative, consistently with the box test.
  const bool direction_negative[3] = {ray_direction_inverse.x < 0.0f,
                                      ray_direction_inverse.y < 0.0f,
                                      ray_direction_inverse.z < 0.0f};
  const BvhNode* nodes = bvh.nodes.data();
  const std::uint32_t* primitive_order = bvh.primitive_order.data();

  Ray search = ray;
  std::optional<BvhHit> closest;
  std::uint32_t stack[kBvhMaxDepth];
  int stack_size = 0;
  std::uint32_t node_index = 0;
  std::uint64_t nodes_visited = 0, primitives_tested = 0;  // locals: kept in registers

  for (;;) {
    const BvhNode& node = nodes[node_index];
    ++nodes_visited;
    if (intersect_ray_box(search, ray_direction_inverse, node.bounds)) {
      if (!node.is_leaf()) {
        const bool second_is_near = direction_negative[node.split_axis];
        stack[stack_size++] = node.first_index + (second_is_near ? 1u : 0u);  // MISTAKE: the near child
        node_index = node.first_index + (second_is_near ? 0u : 1u);  // MISTAKE: the far child
        continue;
      }
      const std::uint32_t leaf_end = node.first_index + node.primitive_count;
      for (std::uint32_t i = node.first_index; i < leaf_end; ++i) {
        const std::uint32_t primitive = primitive_order[i];
        ++primitives_tested;
        if (const std::optional<float> t = intersector.test(intersector.context, search, primitive)) {
          search.t_max = *t;
          closest = BvhHit{*t, primitive};
          if (any_hit) {
            stack_size = 0;  // done: fall through to the exit below
            break;
          }
        }
      }
      if (any_hit && closest) break;
    }
    if (stack_size == 0) break;
    node_index = stack[--stack_size];
  }
  stats.nodes_visited += nodes_visited;
  stats.primitives_tested += primitives_tested;
  return closest;
}

}  // namespace raylab
