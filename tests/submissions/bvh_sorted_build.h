// Grader self-test submissions of stage 05_bvh that build the median split by sorting share this
// build: sort the node's primitives by centroid along an axis (std::sort, no tie-breaking) and
// split at the middle; nodes appended with push_back (no reserve) and referred to by index. A
// submission file says which axis a node at `depth` splits:
//   #define SORTED_BUILD_AXIS(box, depth) (box).longest_axis()
//   #include "bvh_sorted_build.h"
#pragma once

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
  const int axis = SORTED_BUILD_AXIS(box, depth);
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
