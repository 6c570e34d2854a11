// Grader self-test submission (stage 05_bvh), broken: a median-split build that takes the
// longest axis at the root only and below it the axes in turn by depth (x, y, z, x, ...), as a
// KD-tree might. A valid tree with the right hits; the test of the splits finds the inner nodes
// split on another axis than their longest.
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"

#include <algorithm>
#include <numeric>
#undef build_bvh

namespace raylab {
namespace {

void build_sorted(Bvh& bvh, const std::vector<Bounds3>& bounds, std::uint32_t node_index, std::uint32_t begin,
                  std::uint32_t end, std::uint32_t max_leaf_size, int depth) {
  Bounds3 box;
  for (std::uint32_t i = begin; i < end; ++i) box.extend(bounds[bvh.primitive_order[i]]);
  bvh.nodes[node_index].bounds = box;
  if (end - begin <= max_leaf_size) {
    bvh.nodes[node_index].first_index = begin;
    bvh.nodes[node_index].primitive_count = static_cast<std::uint16_t>(end - begin);
    return;
  }
  const int axis = depth == 0 ? box.longest_axis() : depth % 3;  // the mistake below the root
  std::sort(bvh.primitive_order.begin() + begin, bvh.primitive_order.begin() + end,
            [&](std::uint32_t a, std::uint32_t b) { return bounds[a].centroid()[axis] < bounds[b].centroid()[axis]; });
  const std::uint32_t middle = begin + (end - begin) / 2;
  const auto first_child = static_cast<std::uint32_t>(bvh.nodes.size());
  bvh.nodes.push_back(BvhNode{});
  bvh.nodes.push_back(BvhNode{});
  bvh.nodes[node_index].first_index = first_child;  // by index: the push_backs may have moved the array
  bvh.nodes[node_index].split_axis = static_cast<std::uint8_t>(axis);
  build_sorted(bvh, bounds, first_child, begin, middle, max_leaf_size, depth + 1);
  build_sorted(bvh, bounds, first_child + 1, middle, end, max_leaf_size, depth + 1);
}

}  // namespace

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  if (max_leaf_size < 1 || max_leaf_size > kBvhMaxLeafSize) throw std::invalid_argument("build_bvh: bad max_leaf_size");
  Bvh bvh;
  bvh.primitive_order.resize(primitive_bounds.size());
  std::iota(bvh.primitive_order.begin(), bvh.primitive_order.end(), 0u);
  if (primitive_bounds.empty()) return bvh;
  bvh.nodes.push_back(BvhNode{});
  build_sorted(bvh, primitive_bounds, 0, 0, static_cast<std::uint32_t>(primitive_bounds.size()),
               static_cast<std::uint32_t>(max_leaf_size), 0);
  return bvh;
}

}  // namespace raylab
