// Reference solution, stage 05d_kdtree (bonus): a KD-tree built by the surface area heuristic over
// planes at the primitives' box faces, walked front to back. The contract is in
// assignments/05d_kdtree/kdtree.cpp and docs/05d_kdtree.md.
#include "raylab/stages/05d_kdtree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace raylab {
namespace {

constexpr float kInfinityF = std::numeric_limits<float>::infinity();

struct Split {
  int axis = -1;  // -1: no split pays
  float position = 0.0f;
  float cost = kInfinityF;
};

// The area of `cell` with its extent along `axis` set to `extent`.
float area_with(const Bounds3& cell, int axis, float extent) {
  glm::vec3 e = cell.extent();
  e[axis] = extent;
  return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

// The cheapest plane along `axis`, among the faces of the primitives' boxes strictly inside the
// cell, counting with sorted mins, maxes and flat boxes' positions.
void cheapest_plane(const std::vector<Bounds3>& boxes, const std::vector<std::uint32_t>& primitives,
                    const Bounds3& cell, int axis, Split& best) {
  const float low = cell.min[axis], high = cell.max[axis];
  if (!(low < high)) return;
  std::vector<float> mins, maxes, flats, candidates;
  mins.reserve(primitives.size());
  maxes.reserve(primitives.size());
  for (const std::uint32_t p : primitives) {
    const float a = boxes[p].min[axis], b = boxes[p].max[axis];
    mins.push_back(a);
    maxes.push_back(b);
    if (a == b) flats.push_back(a);
    if (a > low && a < high) candidates.push_back(a);
    if (b > low && b < high) candidates.push_back(b);
  }
  std::sort(mins.begin(), mins.end());
  std::sort(maxes.begin(), maxes.end());
  std::sort(flats.begin(), flats.end());
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  const float cell_area = cell.surface_area();
  const auto n = static_cast<float>(primitives.size());
  for (const float s : candidates) {
    const auto below = static_cast<float>(std::lower_bound(mins.begin(), mins.end(), s) - mins.begin()) +
                       static_cast<float>(std::upper_bound(flats.begin(), flats.end(), s) -
                                          std::lower_bound(flats.begin(), flats.end(), s));
    const auto above = n - static_cast<float>(std::upper_bound(maxes.begin(), maxes.end(), s) - maxes.begin());
    const float bonus = (below == 0.0f || above == 0.0f) ? kKdEmptyBonus : 0.0f;
    const float cost = 1.0f + (1.0f - bonus) * (area_with(cell, axis, s - low) / cell_area * below +
                                                area_with(cell, axis, high - s) / cell_area * above);
    if (cost < best.cost) best = {axis, s, cost};
  }
}

struct Builder {
  const std::vector<Bounds3>& boxes;
  KdTree& tree;
  int max_depth;

  void make_leaf(std::uint32_t index, const std::vector<std::uint32_t>& primitives) {
    KdNode& node = tree.nodes[index];
    node.leaf = 1;
    node.first_index = static_cast<std::uint32_t>(tree.primitive_indices.size());
    node.primitive_count = static_cast<std::uint32_t>(primitives.size());
    tree.primitive_indices.insert(tree.primitive_indices.end(), primitives.begin(), primitives.end());
  }

  void build(std::uint32_t index, const std::vector<std::uint32_t>& primitives, const Bounds3& cell, int depth) {
    Split best;
    if (depth < max_depth && primitives.size() > 1 && cell.surface_area() > 0.0f)
      for (int axis = 0; axis < 3; ++axis) cheapest_plane(boxes, primitives, cell, axis, best);
    if (best.axis < 0 || !(best.cost < static_cast<float>(primitives.size()))) {
      make_leaf(index, primitives);
      return;
    }
    std::vector<std::uint32_t> below, above;
    for (const std::uint32_t p : primitives) {
      const Bounds3& box = boxes[p];
      const bool flat_in_plane = box.min[best.axis] == best.position && box.max[best.axis] == best.position;
      if (box.min[best.axis] < best.position || flat_in_plane) below.push_back(p);
      if (box.max[best.axis] > best.position) above.push_back(p);
    }
    const auto first = static_cast<std::uint32_t>(tree.nodes.size());
    tree.nodes.resize(tree.nodes.size() + 2);
    KdNode& node = tree.nodes[index];
    node.leaf = 0;
    node.split_axis = static_cast<std::uint8_t>(best.axis);
    node.split_position = best.position;
    node.first_index = first;
    Bounds3 below_cell = cell, above_cell = cell;
    below_cell.max[best.axis] = best.position;
    above_cell.min[best.axis] = best.position;
    build(first, below, below_cell, depth + 1);
    build(first + 1, above, above_cell, depth + 1);
  }
};

// The ray's interval [t0, t1] inside `box`, within [ray.t_min, ray.t_max]; false when it misses.
// A zero direction component tests the origin against the slab (no 0 * infinity).
bool interval_in_box(const Ray& ray, const Bounds3& box, float& t0, float& t1) {
  t0 = ray.t_min;
  t1 = ray.t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const float o = ray.origin[axis], d = ray.direction[axis];
    if (d == 0.0f) {
      if (o < box.min[axis] || o > box.max[axis]) return false;
      continue;
    }
    float near = (box.min[axis] - o) / d, far = (box.max[axis] - o) / d;
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
  }
  return t0 <= t1;
}

}  // namespace

KdTree build_kdtree(const std::vector<Bounds3>& primitive_bounds) {
  KdTree tree;
  std::vector<std::uint32_t> primitives;
  for (std::uint32_t i = 0; i < primitive_bounds.size(); ++i) {
    const Bounds3& box = primitive_bounds[i];
    if (!(box.min.x <= box.max.x && box.min.y <= box.max.y && box.min.z <= box.max.z)) continue;  // empty, or NaN
    primitives.push_back(i);
    tree.bounds.extend(box);
  }
  if (primitives.empty()) return tree;
  tree.nodes.resize(1);
  Builder builder{primitive_bounds, tree, kdtree_max_depth(primitives.size())};
  builder.build(0, primitives, tree.bounds, 0);
  return tree;
}

std::optional<BvhHit> intersect_kdtree(const KdTree& tree, const Ray& ray, const PrimitiveIntersector& intersector,
                                       bool any_hit, BvhTraversalStats& stats) {
  float t0 = 0.0f, t1 = 0.0f;
  if (tree.nodes.empty() || !interval_in_box(ray, tree.bounds, t0, t1)) return std::nullopt;
  struct Cell {
    std::uint32_t node;
    float t0, t1;
    bool in_plane;  // the other side of a plane the ray lies in: it starts where its sibling starts
  };
  std::array<Cell, kKdMaxDepth + 1> stack;
  int size = 0;
  stack[size++] = {0, t0, t1, false};
  int in_plane_waiting = 0;  // such cells on the stack: while there are, the stack is not in order
  Ray search = ray;          // t_max: the closest hit so far
  std::optional<BvhHit> closest;
  while (size > 0) {
    Cell cell = stack[--size];
    if (cell.in_plane) --in_plane_waiting;
    if (cell.t0 > search.t_max) {  // this cell lies beyond the closest hit, and so does every one after it
      if (in_plane_waiting == 0) break;  // (but for the other side of a plane the ray lies in)
      continue;
    }
    while (true) {
      const KdNode& node = tree.nodes[cell.node];
      ++stats.nodes_visited;
      if (node.is_leaf()) break;
      const int axis = node.split_axis;
      const float o = ray.origin[axis], d = ray.direction[axis], split = node.split_position;
      const bool below_first = o < split || (o == split && d <= 0.0f);
      const std::uint32_t near = below_first ? node.first_index : node.first_index + 1;
      const std::uint32_t far = below_first ? node.first_index + 1 : node.first_index;
      if (d == 0.0f) {
        if (o == split) {  // a ray in the plane: both sides, over the same interval
          stack[size++] = {far, cell.t0, cell.t1, true};
          ++in_plane_waiting;
        }
        cell.node = near;
        continue;
      }
      const float t_split = (split - o) / d;
      if (t_split > cell.t1 || t_split <= 0.0f) {
        cell.node = near;
      } else if (t_split < cell.t0) {
        cell.node = far;
      } else {
        stack[size++] = {far, t_split, cell.t1, false};
        cell = {near, cell.t0, t_split, false};
      }
    }
    const KdNode& leaf = tree.nodes[cell.node];
    for (std::uint32_t i = leaf.first_index; i < leaf.first_index + leaf.primitive_count; ++i) {
      const std::uint32_t primitive = tree.primitive_indices[i];
      ++stats.primitives_tested;
      if (const std::optional<float> t = intersector.test(intersector.context, search, primitive)) {
        if (any_hit) return BvhHit{*t, primitive};
        if (*t < search.t_max) {
          search.t_max = *t;
          closest = BvhHit{*t, primitive};
        }
      }
    }
    // Inside this cell: no later cell holds a nearer one (but the other side of a plane the ray lies
    // in may: it waits with an interval that starts before this cell's end).
    if (closest && closest->t_hit <= cell.t1 && in_plane_waiting == 0) break;
  }
  return closest;
}

}  // namespace raylab
