// Grader self-test submission (stage 05_bvh): a valid build by another rule, the midpoint
// split: the node's longest centroid axis is cut at the middle of the centroids' box
// (std::partition), with a split by count when every centroid falls on one side. A correct
// BVH, but not the median split the contract asks for: expected, only the median-split test
// fails, and its hint says what the contract asked for.
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"

#include <numeric>
#undef build_bvh

namespace raylab {
namespace {

void build_midpoint(Bvh& bvh, const std::vector<Bounds3>& bounds, std::uint32_t node_index, std::uint32_t begin,
                    std::uint32_t end, std::uint32_t max_leaf_size) {
  Bounds3 box, centroid_box;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.extend(bounds[bvh.primitive_order[i]]);
    centroid_box.extend(bounds[bvh.primitive_order[i]].centroid());
  }
  bvh.nodes[node_index].bounds = box;
  if (end - begin <= max_leaf_size) {
    bvh.nodes[node_index].first_index = begin;
    bvh.nodes[node_index].primitive_count = static_cast<std::uint16_t>(end - begin);
    return;
  }
  const int axis = centroid_box.longest_axis();
  const float middle_coordinate = 0.5f * (centroid_box.min[axis] + centroid_box.max[axis]);
  auto* order = bvh.primitive_order.data();
  std::uint32_t middle = static_cast<std::uint32_t>(
      std::partition(order + begin, order + end,
                     [&](std::uint32_t p) { return bounds[p].centroid()[axis] < middle_coordinate; }) -
      order);
  if (middle == begin || middle == end) middle = begin + (end - begin) / 2;  // all on one side
  const auto first_child = static_cast<std::uint32_t>(bvh.nodes.size());
  bvh.nodes.resize(bvh.nodes.size() + 2);
  bvh.nodes[node_index].first_index = first_child;
  bvh.nodes[node_index].split_axis = static_cast<std::uint8_t>(axis);
  build_midpoint(bvh, bounds, first_child, begin, middle, max_leaf_size);
  build_midpoint(bvh, bounds, first_child + 1, middle, end, max_leaf_size);
}

}  // namespace

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  if (max_leaf_size < 1 || max_leaf_size > kBvhMaxLeafSize) throw std::invalid_argument("build_bvh: bad max_leaf_size");
  Bvh bvh;
  bvh.primitive_order.resize(primitive_bounds.size());
  std::iota(bvh.primitive_order.begin(), bvh.primitive_order.end(), 0u);
  if (primitive_bounds.empty()) return bvh;
  bvh.nodes.reserve(2 * primitive_bounds.size());
  bvh.nodes.resize(1);
  build_midpoint(bvh, primitive_bounds, 0, 0, static_cast<std::uint32_t>(primitive_bounds.size()),
                 static_cast<std::uint32_t>(max_leaf_size));
  return bvh;
}

}  // namespace raylab
