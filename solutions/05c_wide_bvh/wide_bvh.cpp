// Reference solution, stage 05c_wide_bvh (a 4-wide BVH with SIMD box tests). The contract is in
// assignments/05c_wide_bvh/wide_bvh.cpp and docs/05c_wide_bvh.md.
#include "raylab/stages/05c_wide_bvh.h"

#include "../04_box/box_slabs.h"
#include "../05_bvh/leaf_test.h"

#include "raylab/math.h"

#include <algorithm>
#include <array>
#include <cstddef>

#if defined(__SSE2__) || defined(_M_X64)
#include <xmmintrin.h>
#define RAYLAB_WIDE_BVH_SSE 1
#endif

namespace raylab {
namespace {

class Collapser {
 public:
  Collapser(const Bvh& binary, Bvh4& wide) : binary_(binary), wide_(wide) {}

  // Makes the wide node of the binary inner node `index` (or, for a leaf root, of that leaf);
  // returns its index in wide_.nodes.
  std::uint32_t collapse(std::uint32_t index) {
    const auto wide_index = static_cast<std::uint32_t>(wide_.nodes.size());
    wide_.nodes.push_back(empty_bvh4_node());
    std::array<std::uint32_t, kBvh4Width> children{};
    int count = 0;
    const BvhNode& node = binary_.nodes[index];
    if (node.is_leaf()) {
      children[count++] = index;
    } else {
      children[count++] = node.first_index;
      children[count++] = node.first_index + 1;
    }
    // Open the inner child of largest surface area until there are four.
    while (count < kBvh4Width) {
      int widest = -1;
      float widest_area = -1.0f;
      for (int i = 0; i < count; ++i) {
        const BvhNode& child = binary_.nodes[children[i]];
        if (child.is_leaf()) continue;
        const float area = child.bounds.surface_area();
        if (area > widest_area) {
          widest_area = area;
          widest = i;
        }
      }
      if (widest < 0) break;
      const std::uint32_t opened = binary_.nodes[children[widest]].first_index;
      children[widest] = opened;
      children[count++] = opened + 1;
    }
    for (int i = 0; i < count; ++i) {
      const BvhNode& child = binary_.nodes[children[i]];
      const Bounds3& box = child.bounds;
      // (wide_.nodes may grow below: index it afresh each time.)
      {
        Bvh4Node& slot = wide_.nodes[wide_index];
        slot.min_x[i] = box.min.x, slot.min_y[i] = box.min.y, slot.min_z[i] = box.min.z;
        slot.max_x[i] = box.max.x, slot.max_y[i] = box.max.y, slot.max_z[i] = box.max.z;
        slot.child_count = static_cast<std::uint8_t>(count);
      }
      if (child.is_leaf()) {
        wide_.nodes[wide_index].child[i] = child.first_index;
        wide_.nodes[wide_index].primitive_count[i] = child.primitive_count;
      } else {
        const std::uint32_t grandchild = collapse(children[i]);
        wide_.nodes[wide_index].child[i] = grandchild;
      }
    }
    return wide_index;
  }

 private:
  const Bvh& binary_;
  Bvh4& wide_;
};

}  // namespace

Bvh4 collapse_bvh4(const Bvh& binary) {
  Bvh4 wide;
  if (binary.nodes.empty()) return wide;
  wide.primitive_order = binary.primitive_order;
  wide.nodes.reserve(binary.nodes.size() / 2 + 1);
  Collapser(binary, wide).collapse(0);
  return wide;
}

namespace {

// intersect_ray_box4's test, here so that the traversal below has it inlined (a call per node
// spills the ray's registers; as stage 05's reference inlines box_slabs.h). The ray's part of
// it (RayLanes: its origin and inverse direction in four lanes each, and which planes it enters
// and leaves by) is made once per ray.
#if RAYLAB_WIDE_BVH_SSE
struct RayLanes {
  __m128 origin[3], inverse[3];
  // Where in a Bvh4Node each axis's entry and exit planes are (bytes from its start): the
  // entry plane is the min plane where the inverse direction is >= 0, the max plane where < 0.
  std::size_t entry_plane[3], exit_plane[3];
  RayLanes(const Ray& ray, const glm::vec3& ray_direction_inverse) {
    const std::size_t lows[3] = {offsetof(Bvh4Node, min_x), offsetof(Bvh4Node, min_y), offsetof(Bvh4Node, min_z)};
    const std::size_t highs[3] = {offsetof(Bvh4Node, max_x), offsetof(Bvh4Node, max_y), offsetof(Bvh4Node, max_z)};
    for (int axis = 0; axis < 3; ++axis) {
      origin[axis] = _mm_set1_ps(ray.origin[axis]);
      inverse[axis] = _mm_set1_ps(ray_direction_inverse[axis]);
      const bool negative = ray_direction_inverse[axis] < 0.0f;
      entry_plane[axis] = negative ? highs[axis] : lows[axis];
      exit_plane[axis] = negative ? lows[axis] : highs[axis];
    }
  }
};

inline unsigned box4_test(const RayLanes& lanes, float t_min, float t_max, const Bvh4Node& node,
                          float entry_distances[kBvh4Width]) {
  const unsigned used = (1u << node.child_count) - 1u;
  // box_slabs.h four lanes at a time: the entry plane chosen by the sign of the inverse
  // direction (the same for all four boxes), the exit scaled up by 1 + 2 gamma(3) (Ize 2013).
  // _mm_max_ps(a, b) and _mm_min_ps(a, b) return b when a is NaN (0 * infinity: the origin on
  // a plane the ray is parallel to), so such a slab leaves the interval as it was.
  const char* const bytes = reinterpret_cast<const char*>(&node);
  __m128 enter = _mm_set1_ps(t_min), exit = _mm_set1_ps(t_max);
  const __m128 widen = _mm_set1_ps(1.0f + 2.0f * gamma_bound(3));
  for (int axis = 0; axis < 3; ++axis) {
    const __m128 near_plane = _mm_loadu_ps(reinterpret_cast<const float*>(bytes + lanes.entry_plane[axis]));
    const __m128 far_plane = _mm_loadu_ps(reinterpret_cast<const float*>(bytes + lanes.exit_plane[axis]));
    const __m128 entry = _mm_mul_ps(_mm_sub_ps(near_plane, lanes.origin[axis]), lanes.inverse[axis]);
    const __m128 leave = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(far_plane, lanes.origin[axis]), lanes.inverse[axis]), widen);
    enter = _mm_max_ps(entry, enter);
    exit = _mm_min_ps(leave, exit);
  }
  _mm_storeu_ps(entry_distances, enter);
  return static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(enter, exit))) & used;
}
#else
struct RayLanes {
  const Ray& ray;
  const glm::vec3& ray_direction_inverse;
};

inline unsigned box4_test(const RayLanes& lanes, float t_min, float t_max, const Bvh4Node& node,
                          float entry_distances[kBvh4Width]) {
  const unsigned used = (1u << node.child_count) - 1u;
  unsigned mask = 0;
  for (int i = 0; i < node.child_count; ++i)
    if (reference::ray_enters_box(lanes.ray.origin, lanes.ray_direction_inverse, node.child_bounds(i), t_min, t_max,
                                  entry_distances[i]))
      mask |= 1u << i;
  return mask & used;
}
#endif

}  // namespace

unsigned intersect_ray_box4(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bvh4Node& node,
                            float entry_distances[kBvh4Width]) {
  return box4_test(RayLanes{ray, ray_direction_inverse}, ray.t_min, ray.t_max, node, entry_distances);
}

namespace {

// The lowest set bit of a nonzero mask.
inline int lowest_set_bit(unsigned mask) {
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctz(mask);
#else
  int bit = 0;
  while (!(mask & (1u << bit))) ++bit;
  return bit;
#endif
}

// Near first: a node's hit leaves tested at once, nearest first; then its nearest hit inner
// child visited next and the other inner children pushed, farthest first. A waiting
// node keeps its entry distance and is dropped without a box test once a closer hit is known.
// test_leaf(search, begin, end, any_hit, closest, tested) tests a leaf's primitives
// (solutions/05_bvh/leaf_test.h): a template parameter, so that the reference's triangle test
// is inlined into the leaf loop (as in solutions/05_bvh/bvh.cpp).
template <typename TestLeaf>
std::optional<BvhHit> traverse4(const Bvh4& bvh, const Ray& ray, bool any_hit, BvhTraversalStats& stats,
                                const TestLeaf& test_leaf) {
  const glm::vec3 ray_direction_inverse = ray_direction_inverse_of(ray);
  const RayLanes lanes{ray, ray_direction_inverse};
  const Bvh4Node* nodes = bvh.nodes.data();
  Ray search = ray;
  std::optional<BvhHit> closest;
  struct Waiting {
    std::uint32_t node;
    float t_enter;
  };
  // Each visit adds at most 4 - 1 waiting nodes, and a collapsed tree is no deeper than its
  // binary tree (kBvhMaxDepth levels).
  Waiting stack[4 * kBvhMaxDepth + 1];
  int stack_size = 0;
  Waiting next{0, ray.t_min};  // the node to visit next: the root first
  std::uint64_t nodes_visited = 0, primitives_tested = 0;
  for (;;) {
    if (!(next.t_enter > search.t_max)) {
      const Bvh4Node& node = nodes[next.node];
      float entries[kBvh4Width];
      unsigned mask = box4_test(lanes, search.t_min, search.t_max, node, entries);
      ++nodes_visited;
      unsigned leaves = 0;
      for (unsigned bits = mask; bits != 0; bits &= bits - 1) {
        const int slot = lowest_set_bit(bits);
        if (node.is_leaf(slot)) leaves |= 1u << slot;
      }
      // Leaves, nearest first (the lowest slot first on a tie, as a stable sort).
      for (unsigned waiting_leaves = leaves; waiting_leaves != 0;) {
        int nearest = lowest_set_bit(waiting_leaves);
        for (unsigned others = waiting_leaves & (waiting_leaves - 1); others != 0; others &= others - 1) {
          const int slot = lowest_set_bit(others);
          if (entries[slot] < entries[nearest]) nearest = slot;
        }
        waiting_leaves &= ~(1u << nearest);
        if (entries[nearest] > search.t_max) continue;
        test_leaf(search, node.child[nearest], node.child[nearest] + node.primitive_count[nearest], any_hit, closest,
                  primitives_tested);
        if (any_hit && closest) break;
      }
      if (any_hit && closest) break;
      // Inner children: the nearest is next; the others pushed, farthest first (sorted by
      // entry distance, stable, so the lowest slot is nearer on a tie).
      unsigned inner = mask & ~leaves;
      if (inner != 0) {
        int order[kBvh4Width], count = 0;
        for (; inner != 0; inner &= inner - 1) {
          const int slot = lowest_set_bit(inner);
#if RAYLAB_WIDE_BVH_SSE
          // fetched while the others are sorted and the nearest visited
          const char* child = reinterpret_cast<const char*>(nodes + node.child[slot]);
          _mm_prefetch(child, _MM_HINT_T0);
          _mm_prefetch(child + 64, _MM_HINT_T0);
#endif
          int at = count++;
          while (at > 0 && entries[order[at - 1]] > entries[slot]) {
            order[at] = order[at - 1];
            --at;
          }
          order[at] = slot;
        }
        for (int k = count - 1; k > 0; --k) stack[stack_size++] = {node.child[order[k]], entries[order[k]]};
        next = {node.child[order[0]], entries[order[0]]};
        continue;
      }
    }
    if (stack_size == 0) break;
    next = stack[--stack_size];
  }
  stats.nodes_visited += nodes_visited;
  stats.primitives_tested += primitives_tested;
  return closest;
}

}  // namespace

std::optional<BvhHit> intersect_bvh4(const Bvh4& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                     bool any_hit, BvhTraversalStats& stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  return reference::with_leaf_test(intersector, bvh.primitive_order.data(), [&](const auto& test_leaf) {
    return traverse4(bvh, ray, any_hit, stats, test_leaf);
  });
}

// The same, the triangles tested inlined (solutions/05_bvh/leaf_test.h).
std::optional<BvhHit> reference::intersect_bvh4_inlined(const Bvh4& bvh, const Ray& ray,
                                                        const LeafTriangles& triangles, bool any_hit,
                                                        BvhTraversalStats& stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  return with_leaf_test(triangles, bvh.primitive_order.data(), [&](const auto& test_leaf) {
    return traverse4(bvh, ray, any_hit, stats, test_leaf);
  });
}

}  // namespace raylab
