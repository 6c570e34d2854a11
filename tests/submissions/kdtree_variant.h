// Grader self-test submissions of stage 05d_kdtree share this implementation, written the plain way
// a student would start (every plane of an axis priced by counting, a std::vector stack): each
// submission sets the flags of its mistakes (or of a correct variant), so that its file says only
// what it changes.
#pragma once

#include "raylab/stages/05d_kdtree.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace raylab::submission {

struct KdTreeVariant {
  // Mistakes of the build.
  bool lost_at_split = false;     // a primitive goes to the side of its box's centre only
  bool median_planes = false;     // each plane at the middle of the cell's longest axis, until 8 or fewer remain
  bool centroid_planes = false;   // the SAH's planes at the primitives' centres, not at their boxes' faces
  bool bounds_padded = false;     // tree.bounds grown by 0.01 on every side
  bool empty_boxes_listed = false;  // primitives with an empty box go into the tree too
  bool flat_dropped = false;      // a box that lies in the plane goes to neither side
  bool one_level_too_deep = false;  // splits down to depth kdtree_max_depth + 1
  bool planes_on_faces = false;   // the cell's own faces are candidate planes too
  // Mistakes of the walk.
  bool hit_beyond_cell = false;   // returns after the first leaf with a hit, wherever the hit lies
  bool interval_not_cut = false;  // the near child keeps the parent's interval end
  bool far_first = false;         // the far side of each plane first
  bool never_stops = false;       // walks every cell the ray crosses
  bool any_hit_goes_on = false;   // any_hit: searches on for the closest hit
  bool nodes_not_counted = false;  // stats.nodes_visited never incremented
  bool primitives_not_counted = false;  // stats.primitives_tested never incremented
  bool position_not_index = false;  // a hit names the position i in primitive_indices, not primitive_indices[i]
  // Correct variants.
  bool binned = false;            // planes at 32 evenly spaced bins per axis rather than at the boxes' faces
};

inline KdTreeVariant kdtree_variant() {
  KdTreeVariant v;
  KDTREE_VARIANT(v);
  return v;
}

}  // namespace raylab::submission

namespace raylab {
namespace {

float cell_area_with(const Bounds3& cell, int axis, float extent) {
  glm::vec3 e = cell.extent();
  e[axis] = extent;
  return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

void build_node(const std::vector<Bounds3>& boxes, KdTree& tree, std::uint32_t index,
                const std::vector<std::uint32_t>& primitives, const Bounds3& cell, int depth, int max_depth) {
  const submission::KdTreeVariant v = submission::kdtree_variant();
  int best_axis = -1;
  float best_position = 0.0f, best_cost = static_cast<float>(primitives.size());
  if (depth < max_depth && primitives.size() > 1 && cell.surface_area() > 0.0f) {
    if (v.median_planes) {  // (a plane every primitive crosses is no split: a leaf)
      const int axis = cell.longest_axis();
      const float middle = 0.5f * (cell.min[axis] + cell.max[axis]);
      std::size_t crossing = 0;
      for (const std::uint32_t p : primitives) crossing += boxes[p].min[axis] < middle && boxes[p].max[axis] > middle;
      if (primitives.size() > 8 && 4 * crossing < primitives.size()) best_axis = axis, best_position = middle;
    } else {
      for (int axis = 0; axis < 3; ++axis) {
        std::vector<float> planes;
        if (v.binned) {
          for (int b = 1; b < 32; ++b) planes.push_back(cell.min[axis] + (cell.max[axis] - cell.min[axis]) * float(b) / 32.0f);
        } else if (v.centroid_planes) {
          for (const std::uint32_t p : primitives) planes.push_back(boxes[p].centroid()[axis]);
        } else {
          for (const std::uint32_t p : primitives) {
            planes.push_back(boxes[p].min[axis]);
            planes.push_back(boxes[p].max[axis]);
          }
        }
        for (const float s : planes) {
          if (!(s > cell.min[axis] && s < cell.max[axis]) && !(v.planes_on_faces && s >= cell.min[axis] && s <= cell.max[axis]))
            continue;
          float below = 0.0f, above = 0.0f;
          for (const std::uint32_t p : primitives) {
            if (boxes[p].min[axis] < s || (boxes[p].min[axis] == s && boxes[p].max[axis] == s)) below += 1.0f;
            if (boxes[p].max[axis] > s) above += 1.0f;
          }
          const float bonus = (below == 0.0f || above == 0.0f) ? kKdEmptyBonus : 0.0f;
          const float cost = 1.0f + (1.0f - bonus) * (cell_area_with(cell, axis, s - cell.min[axis]) * below +
                                                      cell_area_with(cell, axis, cell.max[axis] - s) * above) /
                                        cell.surface_area();
          if (cost < best_cost) best_axis = axis, best_position = s, best_cost = cost;
        }
      }
    }
  }
  if (best_axis < 0) {
    tree.nodes[index].leaf = 1;
    tree.nodes[index].first_index = static_cast<std::uint32_t>(tree.primitive_indices.size());
    tree.nodes[index].primitive_count = static_cast<std::uint32_t>(primitives.size());
    tree.primitive_indices.insert(tree.primitive_indices.end(), primitives.begin(), primitives.end());
    return;
  }
  std::vector<std::uint32_t> below, above;
  for (const std::uint32_t p : primitives) {
    const Bounds3& box = boxes[p];
    if (v.lost_at_split) {
      (box.centroid()[best_axis] < best_position ? below : above).push_back(p);
      continue;
    }
    const bool flat_in_plane = box.min[best_axis] == best_position && box.max[best_axis] == best_position;
    if (box.min[best_axis] < best_position || (flat_in_plane && !v.flat_dropped)) below.push_back(p);
    if (box.max[best_axis] > best_position) above.push_back(p);
  }
  const auto first = static_cast<std::uint32_t>(tree.nodes.size());
  tree.nodes.resize(tree.nodes.size() + 2);
  tree.nodes[index].split_axis = static_cast<std::uint8_t>(best_axis);
  tree.nodes[index].split_position = best_position;
  tree.nodes[index].first_index = first;
  Bounds3 below_cell = cell, above_cell = cell;
  below_cell.max[best_axis] = best_position;
  above_cell.min[best_axis] = best_position;
  build_node(boxes, tree, first, below, below_cell, depth + 1, max_depth);
  build_node(boxes, tree, first + 1, above, above_cell, depth + 1, max_depth);
}

}  // namespace

KdTree build_kdtree(const std::vector<Bounds3>& primitive_bounds) {
  const submission::KdTreeVariant v = submission::kdtree_variant();
  KdTree tree;
  std::vector<std::uint32_t> primitives;
  for (std::uint32_t i = 0; i < primitive_bounds.size(); ++i)
    if (!primitive_bounds[i].is_empty() || v.empty_boxes_listed) {
      primitives.push_back(i);
      tree.bounds.extend(primitive_bounds[i]);
    }
  if (primitives.empty()) return tree;
  if (v.bounds_padded) {
    tree.bounds.min -= glm::vec3(0.01f);
    tree.bounds.max += glm::vec3(0.01f);
  }
  tree.nodes.resize(1);
  const int max_depth = kdtree_max_depth(primitives.size()) + (v.one_level_too_deep ? 1 : 0);
  build_node(primitive_bounds, tree, 0, primitives, tree.bounds, 0, max_depth);
  return tree;
}

std::optional<BvhHit> intersect_kdtree(const KdTree& tree, const Ray& ray, const PrimitiveIntersector& intersector,
                                       bool any_hit, BvhTraversalStats& stats) {
  const submission::KdTreeVariant v = submission::kdtree_variant();
  if (tree.nodes.empty()) return std::nullopt;
  float t0 = ray.t_min, t1 = ray.t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const float o = ray.origin[axis], d = ray.direction[axis];
    if (d == 0.0f) {
      if (o < tree.bounds.min[axis] || o > tree.bounds.max[axis]) return std::nullopt;
      continue;
    }
    const float a = (tree.bounds.min[axis] - o) / d, b = (tree.bounds.max[axis] - o) / d;
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  if (!(t0 <= t1)) return std::nullopt;
  struct Cell {
    std::uint32_t node;
    float t0, t1;
    bool in_plane;
  };
  std::vector<Cell> stack{{0u, t0, t1, false}};
  int in_plane_waiting = 0;
  Ray search = ray;
  std::optional<BvhHit> closest;
  while (!stack.empty()) {
    Cell cell = stack.back();
    stack.pop_back();
    if (cell.in_plane) --in_plane_waiting;
    if (!v.never_stops && closest && cell.t0 > closest->t_hit) {
      if (in_plane_waiting == 0) break;
      continue;
    }
    while (true) {
      const KdNode& node = tree.nodes[cell.node];
      if (!v.nodes_not_counted) ++stats.nodes_visited;
      if (node.is_leaf()) break;
      const float o = ray.origin[node.split_axis], d = ray.direction[node.split_axis], s = node.split_position;
      const bool below_first = o < s || (o == s && d <= 0.0f);
      const std::uint32_t near = below_first ? node.first_index : node.first_index + 1;
      const std::uint32_t far = below_first ? node.first_index + 1 : node.first_index;
      if (d == 0.0f) {
        if (o == s) stack.push_back({far, cell.t0, cell.t1, true}), ++in_plane_waiting;
        cell.node = near;
        continue;
      }
      const float t_split = (s - o) / d;
      if (t_split > cell.t1 || t_split <= 0.0f) {
        cell.node = near;
      } else if (t_split < cell.t0) {
        cell.node = far;
      } else if (v.far_first) {  // the far cell first, the near one afterwards
        stack.push_back({near, cell.t0, v.interval_not_cut ? cell.t1 : t_split, false});
        cell = {far, t_split, cell.t1, false};
      } else {
        stack.push_back({far, t_split, cell.t1, false});
        cell = {near, cell.t0, v.interval_not_cut ? cell.t1 : t_split, false};
      }
    }
    const KdNode& leaf = tree.nodes[cell.node];
    for (std::uint32_t i = leaf.first_index; i < leaf.first_index + leaf.primitive_count; ++i) {
      if (!v.primitives_not_counted) ++stats.primitives_tested;
      if (const std::optional<float> t = intersector.test(intersector.context, search, tree.primitive_indices[i])) {
        const std::uint32_t named = v.position_not_index ? i : tree.primitive_indices[i];
        if (any_hit && !v.any_hit_goes_on) return BvhHit{*t, named};
        search.t_max = *t;
        closest = BvhHit{*t, named};
      }
    }
    if (closest && !v.never_stops &&
        (v.hit_beyond_cell || (closest->t_hit <= cell.t1 && in_plane_waiting == 0)))
      break;
  }
  return closest;
}

}  // namespace raylab
