// Grader self-test submission (stage 05_bvh): a median-split build that keeps a BvhNode&
// to the node being built while its children are pushed back, without reserving the array:
// when nodes.push_back grows the vector, the reference dangles, and the node's first_index
// and split_axis, written after the children are built, are lost (the node keeps a new
// node's first_index 0 and primitive_count 0).
//
// A write through a dangling reference is undefined behaviour (it may corrupt the heap or
// crash); so that this self-test is deterministic, the reference here points into a copy of
// the array made before each push_back, which is what a student sees when the freed memory
// is not reused: the writes land where nobody reads them. Expected hint: the invariant
// failure naming "a BvhNode& taken before a nodes.push_back".
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh

#include <list>
#include <algorithm>
#include <numeric>

namespace raylab {
namespace {

struct DanglingBuilder {
  const std::vector<Bounds3>& bounds;
  std::uint32_t max_leaf_size;
  Bvh bvh;
  std::list<std::vector<BvhNode, BvhNodeAllocator<BvhNode>>> old_arrays;  // where the dangling writes land
  std::vector<BvhNode**> live_references;      // the `node` of every build_node in progress

  // nodes.push_back; when the vector grows, every reference into the array is left pointing
  // at the old array, as a real reallocation does.
  void push_back_node() {
    if (bvh.nodes.size() == bvh.nodes.capacity()) {
      old_arrays.push_back(bvh.nodes);
      for (BvhNode** node : live_references)
        if (*node >= bvh.nodes.data() && *node < bvh.nodes.data() + bvh.nodes.size())
          *node = old_arrays.back().data() + (*node - bvh.nodes.data());
    }
    bvh.nodes.emplace_back();
  }

  void build_node(std::uint32_t node_index, std::uint32_t begin, std::uint32_t end) {
    BvhNode* node = &bvh.nodes[node_index];  // MISTAKE: kept across push_back below
    live_references.push_back(&node);
    Bounds3 box;
    for (std::uint32_t i = begin; i < end; ++i) box.extend(bounds[bvh.primitive_order[i]]);
    node->bounds = box;
    if (end - begin <= max_leaf_size) {
      node->first_index = begin;
      node->primitive_count = static_cast<std::uint16_t>(end - begin);
      live_references.pop_back();
      return;
    }
    const int axis = box.longest_axis();
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(bvh.primitive_order.begin() + begin, bvh.primitive_order.begin() + middle,
                     bvh.primitive_order.begin() + end, [&](std::uint32_t a, std::uint32_t b) {
                       return bounds[a].centroid()[axis] < bounds[b].centroid()[axis];
                     });
    const auto first_child = static_cast<std::uint32_t>(bvh.nodes.size());
    push_back_node();
    push_back_node();
    build_node(first_child, begin, middle);
    build_node(first_child + 1, middle, end);
    node->first_index = first_child;  // lost when the array moved
    node->primitive_count = 0;
    node->split_axis = static_cast<std::uint8_t>(axis);
    live_references.pop_back();
  }
};

}  // namespace

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  DanglingBuilder builder{primitive_bounds, static_cast<std::uint32_t>(max_leaf_size), {}, {}, {}};
  builder.bvh.primitive_order.resize(primitive_bounds.size());
  std::iota(builder.bvh.primitive_order.begin(), builder.bvh.primitive_order.end(), 0u);
  if (primitive_bounds.empty()) return builder.bvh;
  builder.bvh.nodes.emplace_back();
  builder.build_node(0, 0, static_cast<std::uint32_t>(primitive_bounds.size()));
  return builder.bvh;
}

}  // namespace raylab
