// Grader self-test submissions of stage 05c_wide_bvh share this implementation, written the plain
// way a student would start (a loop over the four slots, no SIMD): each submission sets the flags
// of its mistakes (or of a correct variant), so that its file says only what it changes.
#pragma once

#include "raylab/math.h"
#include "raylab/stages/05c_wide_bvh.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace raylab::submission {

struct WideBvhVariant {
  // Mistakes.
  bool no_collapse = false;          // every wide node is one binary node with its two children
  bool nan_loses_the_box = false;    // max(enter, 0 * infinity) taken as NaN: the box is lost
  bool min_max_slabs_unmasked = false;  // slabs by min/max of the two planes, empty slots not masked
  bool far_first_no_pruning = false;  // children visited farthest first, nothing skipped beyond a hit
  bool order_reversed = false;       // the wide tree's primitive_order reversed (the leaves' ranges kept)
  bool empty_slots_zero_boxes = false;  // unused slots get the box [0, 0] instead of empty_bvh4_node()'s
  bool boxes_shrunk = false;         // every slot's box shrunk by a tenth of its size on x
  bool leaf_root_dropped = false;    // a binary tree of one leaf gives a wide root with no child
  bool empty_tree_gets_a_node = false;  // an empty binary tree gives one empty wide node
  bool box4_ignores_t_max = false;   // intersect_ray_box4 exits at infinity, not at ray.t_max
  bool box4_ignores_t_min = false;   // intersect_ray_box4 enters at -infinity, not at ray.t_min: boxes behind count
  bool entry_is_exit = false;        // entry_distances[i] is where the ray leaves the box
  bool nodes_not_counted = false;    // stats.nodes_visited never incremented
  bool nodes_counted_once = false;   // stats.nodes_visited incremented once per ray, before the loop
  bool primitives_not_counted = false;  // stats.primitives_tested never incremented
  bool any_hit_goes_on = false;      // any_hit: searches on for the closest hit (right answers, more work)
  // Correct variants.
  bool two_levels = false;  // the collapse takes the grandchildren of both children, no surface areas
};

inline WideBvhVariant wide_bvh_variant() {
  WideBvhVariant v;
  WIDE_BVH_VARIANT(v);
  return v;
}

}  // namespace raylab::submission

namespace raylab {
namespace {

std::uint32_t collapse_node(const Bvh& binary, std::uint32_t index, Bvh4& wide) {
  const submission::WideBvhVariant v = submission::wide_bvh_variant();
  const auto at = static_cast<std::uint32_t>(wide.nodes.size());
  wide.nodes.push_back(empty_bvh4_node());
  std::vector<std::uint32_t> children;
  const BvhNode& node = binary.nodes[index];
  if (node.is_leaf()) {
    if (!v.leaf_root_dropped) children = {index};
  } else if (v.no_collapse) {
    children = {node.first_index, node.first_index + 1};
  } else if (v.two_levels) {
    for (const std::uint32_t child : {node.first_index, node.first_index + 1}) {
      if (binary.nodes[child].is_leaf()) {
        children.push_back(child);
      } else {
        children.push_back(binary.nodes[child].first_index);
        children.push_back(binary.nodes[child].first_index + 1);
      }
    }
  } else {
    children = {node.first_index, node.first_index + 1};
    while (children.size() < 4) {
      std::size_t widest = children.size();
      for (std::size_t i = 0; i < children.size(); ++i)
        if (!binary.nodes[children[i]].is_leaf() &&
            (widest == children.size() ||
             binary.nodes[children[i]].bounds.surface_area() > binary.nodes[children[widest]].bounds.surface_area()))
          widest = i;
      if (widest == children.size()) break;
      const std::uint32_t opened = binary.nodes[children[widest]].first_index;
      children[widest] = opened;
      children.push_back(opened + 1);
    }
  }
  wide.nodes[at].child_count = static_cast<std::uint8_t>(children.size());
  if (v.empty_slots_zero_boxes)
    for (std::size_t i = children.size(); i < kBvh4Width; ++i) {
      Bvh4Node& slot = wide.nodes[at];
      slot.min_x[i] = slot.min_y[i] = slot.min_z[i] = slot.max_x[i] = slot.max_y[i] = slot.max_z[i] = 0.0f;
    }
  for (std::size_t i = 0; i < children.size(); ++i) {
    const BvhNode& child = binary.nodes[children[i]];
    Bvh4Node& slot = wide.nodes[at];
    slot.min_x[i] = child.bounds.min.x, slot.min_y[i] = child.bounds.min.y, slot.min_z[i] = child.bounds.min.z;
    slot.max_x[i] = child.bounds.max.x, slot.max_y[i] = child.bounds.max.y, slot.max_z[i] = child.bounds.max.z;
    if (v.boxes_shrunk) slot.max_x[i] -= 0.1f * (child.bounds.max.x - child.bounds.min.x);
    if (child.is_leaf()) {
      wide.nodes[at].child[i] = child.first_index;
      wide.nodes[at].primitive_count[i] = child.primitive_count;
    } else {
      const std::uint32_t below = collapse_node(binary, children[i], wide);
      wide.nodes[at].child[i] = below;
    }
  }
  return at;
}

}  // namespace

Bvh4 collapse_bvh4(const Bvh& binary) {
  const submission::WideBvhVariant v = submission::wide_bvh_variant();
  Bvh4 wide;
  if (binary.nodes.empty()) {
    if (v.empty_tree_gets_a_node) wide.nodes.push_back(empty_bvh4_node());
    return wide;
  }
  wide.primitive_order = binary.primitive_order;
  if (v.order_reversed) std::reverse(wide.primitive_order.begin(), wide.primitive_order.end());
  collapse_node(binary, 0, wide);
  return wide;
}

unsigned intersect_ray_box4(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bvh4Node& node,
                            float entry_distances[kBvh4Width]) {
  const submission::WideBvhVariant v = submission::wide_bvh_variant();
  unsigned mask = 0;
  const int slots = v.min_max_slabs_unmasked ? kBvh4Width : node.child_count;
  for (int i = 0; i < slots; ++i) {
    const Bounds3 box = node.child_bounds(i);
    float enter = v.box4_ignores_t_min ? -kInfinity : ray.t_min, exit = v.box4_ignores_t_max ? kInfinity : ray.t_max;
    for (int axis = 0; axis < 3; ++axis) {
      const float inverse = ray_direction_inverse[axis];
      float near_t, far_t;
      if (v.min_max_slabs_unmasked) {
        const float a = (box.min[axis] - ray.origin[axis]) * inverse, b = (box.max[axis] - ray.origin[axis]) * inverse;
        near_t = std::min(a, b);
        far_t = std::max(a, b);
      } else {
        const bool negative = inverse < 0.0f;
        near_t = ((negative ? box.max[axis] : box.min[axis]) - ray.origin[axis]) * inverse;
        far_t = ((negative ? box.min[axis] : box.max[axis]) - ray.origin[axis]) * inverse;
      }
      far_t *= 1.0f + 2.0f * gamma_bound(3);
      if (v.nan_loses_the_box) {
        enter = (near_t > enter || std::isnan(near_t)) ? near_t : enter;
        exit = (far_t < exit || std::isnan(far_t)) ? far_t : exit;
      } else {
        if (near_t > enter) enter = near_t;
        if (far_t < exit) exit = far_t;
      }
    }
    entry_distances[i] = v.entry_is_exit ? exit : enter;
    if (enter <= exit) mask |= 1u << i;
  }
  return mask;
}

std::optional<BvhHit> intersect_bvh4(const Bvh4& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                     bool any_hit, BvhTraversalStats& stats) {
  const submission::WideBvhVariant v = submission::wide_bvh_variant();
  if (bvh.nodes.empty()) return std::nullopt;
  const glm::vec3 inverse = ray_direction_inverse_of(ray);
  Ray search = ray;
  std::optional<BvhHit> closest;
  std::vector<std::pair<float, std::uint32_t>> waiting{{ray.t_min, 0u}};
  if (v.nodes_counted_once) ++stats.nodes_visited;
  while (!waiting.empty()) {
    const auto [enter, index] = waiting.back();
    waiting.pop_back();
    if (!v.far_first_no_pruning && enter > search.t_max) continue;
    const Bvh4Node& node = bvh.nodes[index];
    float entries[kBvh4Width];
    const unsigned mask = intersect_ray_box4(v.far_first_no_pruning ? ray : search, inverse, node, entries);
    if (!v.nodes_not_counted && !v.nodes_counted_once) ++stats.nodes_visited;
    std::vector<std::pair<float, int>> hit;
    for (int i = 0; i < node.child_count; ++i)
      if (mask & (1u << i)) hit.push_back({entries[i], i});
    std::sort(hit.begin(), hit.end());
    if (v.far_first_no_pruning) std::reverse(hit.begin(), hit.end());
    for (const auto& [entry, slot] : hit) {
      if (!node.is_leaf(slot)) continue;
      for (std::uint32_t k = node.child[slot]; k < node.child[slot] + node.primitive_count[slot]; ++k) {
        if (!v.primitives_not_counted) ++stats.primitives_tested;
        if (const std::optional<float> t = intersector.test(intersector.context, search, bvh.primitive_order[k])) {
          search.t_max = *t;
          closest = BvhHit{*t, bvh.primitive_order[k]};
          if (any_hit && !v.any_hit_goes_on) return closest;
        }
      }
    }
    for (auto it = hit.rbegin(); it != hit.rend(); ++it)
      if (!node.is_leaf(it->second)) waiting.push_back({it->first, node.child[it->second]});
  }
  return closest;
}

}  // namespace raylab
