// The reference's fastest tree: stage 05c's 4-wide tree made 8 wide, its eight boxes tested
// at once with AVX2 where the CPU has it (chosen at run time: the default build assumes no more
// than SSE2). raylab-reference and bench/ trace it instead of the 4-wide tree
// (solutions/05c_wide_bvh/fast_tree.h). Its leaves are whole subtrees of the
// binary tree of up to 8 triangles, tested in one pass of eight lanes (moller_trumbore4 of
// solutions/05_bvh/leaf_test.h made 8 wide): the tree has fewer nodes and a ray tests fewer
// leaves, each for about the work of four lanes. The same visit rule as
// solutions/05c_wide_bvh/wide_bvh.cpp's traverse4. The same closest t, except that where a ray
// meets a vertex the triangles around it give t's an ulp apart and trees of other widths may
// prune between them (as the 4-wide tree already does against the binary one): the course
// scenes render to the same bits either way (tests/test_render.cpp). Not a stage and not part
// of any student contract; docs/performance.md, "BVH traversal", measures it.
#pragma once

#include "../05_bvh/leaf_test.h"

#include "raylab/avx2.h"
#include "raylab/math.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace raylab::reference {

// Whether the 8-wide tree is traced on this machine (else the 4-wide one is).
inline bool eight_wide_tree_runs_here() { return avx2_runs_here(); }

#if RAYLAB_AVX2_COMPILES
constexpr int kBvh8Width = 8;

// As Bvh4Node (raylab/stages/05c_wide_bvh.h), eight slots: 256 bytes, four cache lines.
struct alignas(64) Bvh8Node {
  float min_x[kBvh8Width], min_y[kBvh8Width], min_z[kBvh8Width];
  float max_x[kBvh8Width], max_y[kBvh8Width], max_z[kBvh8Width];
  std::uint32_t child[kBvh8Width];
  std::uint16_t primitive_count[kBvh8Width];
  std::uint8_t child_count = 0;
  std::uint8_t leaf_slots = 0;  // bit i set: slot i is a leaf, its triangles child[i] .. + primitive_count[i]
  std::uint8_t padding[14] = {};
};
static_assert(sizeof(Bvh8Node) == 256, "a Bvh8Node is four cache lines");

struct Bvh8 {
  std::vector<Bvh8Node> nodes;
  std::vector<std::uint32_t> primitive_order;  // the binary tree's, unchanged
};

// A subtree of the binary tree with at most this many primitives is one leaf of the 8-wide tree,
// its triangles tested in one pass of eight lanes (EightAtATime below).
constexpr std::uint32_t kBvh8LeafSize = 8;

// Under each node of the binary tree: the positions [begin, end) of primitive_order its leaves
// hold, when they are one run (a build that partitions in place, as the reference's, makes
// every subtree one); else begin > end. Children come after their parent in the node array.
struct PrimitiveRun {
  std::uint32_t begin = 1, end = 0;
  bool fits_one_leaf() const { return begin <= end && end - begin <= kBvh8LeafSize; }
};
inline std::vector<PrimitiveRun> primitive_runs(const Bvh& binary) {
  std::vector<PrimitiveRun> runs(binary.nodes.size());
  for (std::size_t i = binary.nodes.size(); i-- > 0;) {
    const BvhNode& node = binary.nodes[i];
    if (node.is_leaf()) {
      runs[i] = {node.first_index, node.first_index + node.primitive_count};
    } else if (node.first_index > i && node.first_index + 1 < binary.nodes.size()) {
      const PrimitiveRun& a = runs[node.first_index];
      const PrimitiveRun& b = runs[node.first_index + 1];
      if (a.begin <= a.end && b.begin <= b.end) {
        if (a.end == b.begin) runs[i] = {a.begin, b.end};
        if (b.end == a.begin) runs[i] = {b.begin, a.end};
      }
    }
  }
  return runs;
}

// As collapse_bvh4: open the inner child of largest surface area until there are eight; a
// child whose subtree fits one leaf (kBvh8LeafSize) is not opened but becomes that leaf.
inline std::uint32_t collapse_into_bvh8(const Bvh& binary, const std::vector<PrimitiveRun>& runs, Bvh8& wide,
                                        std::uint32_t index) {
  const auto wide_index = static_cast<std::uint32_t>(wide.nodes.size());
  Bvh8Node empty;
  for (int i = 0; i < kBvh8Width; ++i) {
    empty.min_x[i] = empty.min_y[i] = empty.min_z[i] = kInfinity;
    empty.max_x[i] = empty.max_y[i] = empty.max_z[i] = -kInfinity;
    empty.child[i] = 0;
    empty.primitive_count[i] = 0;
  }
  wide.nodes.push_back(empty);
  std::array<std::uint32_t, kBvh8Width> children{};
  int count = 0;
  const BvhNode& node = binary.nodes[index];
  const auto is_wide_leaf = [&](std::uint32_t child) {
    return binary.nodes[child].is_leaf() || runs[child].fits_one_leaf();
  };
  if (is_wide_leaf(index)) {
    children[count++] = index;
  } else {
    children[count++] = node.first_index;
    children[count++] = node.first_index + 1;
  }
  while (count < kBvh8Width) {
    int widest = -1;
    float widest_area = -1.0f;
    for (int i = 0; i < count; ++i) {
      const BvhNode& child = binary.nodes[children[i]];
      if (is_wide_leaf(children[i])) continue;
      const float area = child.bounds.surface_area();
      if (area > widest_area) {
        widest_area = area;
        widest = i;
      }
    }
    if (widest < 0) break;
    const std::uint32_t opened = binary.nodes[children[widest]].first_index;
    children[widest] = opened;
    children[count++] = opened + 1;
  }
  for (int i = 0; i < count; ++i) {
    const BvhNode& child = binary.nodes[children[i]];
    const Bounds3& box = child.bounds;
    {
      Bvh8Node& slot = wide.nodes[wide_index];  // (wide.nodes grows below: indexed afresh)
      slot.min_x[i] = box.min.x, slot.min_y[i] = box.min.y, slot.min_z[i] = box.min.z;
      slot.max_x[i] = box.max.x, slot.max_y[i] = box.max.y, slot.max_z[i] = box.max.z;
      slot.child_count = static_cast<std::uint8_t>(count);
    }
    if (is_wide_leaf(children[i])) {
      const PrimitiveRun run = runs[children[i]];
      wide.nodes[wide_index].child[i] = run.begin;
      wide.nodes[wide_index].primitive_count[i] = static_cast<std::uint16_t>(run.end - run.begin);
      wide.nodes[wide_index].leaf_slots = static_cast<std::uint8_t>(wide.nodes[wide_index].leaf_slots | (1u << i));
    } else {
      const std::uint32_t grandchild = collapse_into_bvh8(binary, runs, wide, children[i]);
      wide.nodes[wide_index].child[i] = grandchild;
    }
  }
  return wide_index;
}

inline Bvh8 collapse_bvh8(const Bvh& binary) {
  Bvh8 wide;
  if (binary.nodes.empty()) return wide;
  wide.primitive_order = binary.primitive_order;
  wide.nodes.reserve(binary.nodes.size() / 4 + 1);
  collapse_into_bvh8(binary, primitive_runs(binary), wide, 0);
  return wide;
}

// (x + y) + z, as glm::dot, in eight lanes.
__attribute__((target("avx2"))) inline __m256 dot8(__m256 ax, __m256 ay, __m256 az, __m256 bx, __m256 by, __m256 bz) {
  return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(ax, bx), _mm256_mul_ps(ay, by)), _mm256_mul_ps(az, bz));
}

// moller_trumbore4 (solutions/05_bvh/leaf_test.h) in eight lanes, the same operations in the
// same order: the triangles at positions [first, first + 8) of the columns. Returns the mask
// of the lanes hit in (ray.t_min, ray.t_max), their t and barycentrics in t_hit, b1 and b2.
__attribute__((target("avx2"))) inline unsigned moller_trumbore8(const Ray& ray, const TriangleColumns& columns,
                                                                 std::uint32_t first, float t_hit[8], float b1_hit[8],
                                                                 float b2_hit[8]) {
  // (No lambdas here: they would not be compiled for AVX2.)
  const float* const at = columns.values + first;
  const std::size_t stride = columns.stride;
  const __m256 p0_x = _mm256_loadu_ps(at), p0_y = _mm256_loadu_ps(at + stride), p0_z = _mm256_loadu_ps(at + 2 * stride);
  const __m256 e1_x = _mm256_loadu_ps(at + 3 * stride), e1_y = _mm256_loadu_ps(at + 4 * stride),
               e1_z = _mm256_loadu_ps(at + 5 * stride);
  const __m256 e2_x = _mm256_loadu_ps(at + 6 * stride), e2_y = _mm256_loadu_ps(at + 7 * stride),
               e2_z = _mm256_loadu_ps(at + 8 * stride);
  const __m256 d_x = _mm256_set1_ps(ray.direction.x), d_y = _mm256_set1_ps(ray.direction.y),
               d_z = _mm256_set1_ps(ray.direction.z);
  // glm::cross(direction, edge_02)
  const __m256 c_x = _mm256_sub_ps(_mm256_mul_ps(d_y, e2_z), _mm256_mul_ps(e2_y, d_z));
  const __m256 c_y = _mm256_sub_ps(_mm256_mul_ps(d_z, e2_x), _mm256_mul_ps(e2_z, d_x));
  const __m256 c_z = _mm256_sub_ps(_mm256_mul_ps(d_x, e2_y), _mm256_mul_ps(e2_x, d_y));
  const __m256 determinant = dot8(e1_x, e1_y, e1_z, c_x, c_y, c_z);
  // != 0 (true for NaN, as in C++) and finite: |determinant| < infinity (false for NaN).
  const __m256 absolute = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), determinant);
  __m256 hit = _mm256_and_ps(_mm256_cmp_ps(determinant, _mm256_setzero_ps(), _CMP_NEQ_UQ),
                             _mm256_cmp_ps(absolute, _mm256_set1_ps(kInfinity), _CMP_LT_OQ));
  const __m256 inverse_determinant = _mm256_div_ps(_mm256_set1_ps(1.0f), determinant);
  const __m256 o_x = _mm256_sub_ps(_mm256_set1_ps(ray.origin.x), p0_x),
               o_y = _mm256_sub_ps(_mm256_set1_ps(ray.origin.y), p0_y),
               o_z = _mm256_sub_ps(_mm256_set1_ps(ray.origin.z), p0_z);
  const __m256 b1 = _mm256_mul_ps(dot8(o_x, o_y, o_z, c_x, c_y, c_z), inverse_determinant);
  hit = _mm256_and_ps(hit, _mm256_and_ps(_mm256_cmp_ps(b1, _mm256_setzero_ps(), _CMP_GE_OQ),
                                         _mm256_cmp_ps(b1, _mm256_set1_ps(1.0f), _CMP_LE_OQ)));
  // glm::cross(p0_to_origin, edge_01)
  const __m256 q_x = _mm256_sub_ps(_mm256_mul_ps(o_y, e1_z), _mm256_mul_ps(e1_y, o_z));
  const __m256 q_y = _mm256_sub_ps(_mm256_mul_ps(o_z, e1_x), _mm256_mul_ps(e1_z, o_x));
  const __m256 q_z = _mm256_sub_ps(_mm256_mul_ps(o_x, e1_y), _mm256_mul_ps(e1_x, o_y));
  const __m256 b2 = _mm256_mul_ps(dot8(d_x, d_y, d_z, q_x, q_y, q_z), inverse_determinant);
  hit = _mm256_and_ps(hit, _mm256_and_ps(_mm256_cmp_ps(b2, _mm256_setzero_ps(), _CMP_GE_OQ),
                                         _mm256_cmp_ps(_mm256_add_ps(b1, b2), _mm256_set1_ps(1.0f), _CMP_LE_OQ)));
  const __m256 t = _mm256_mul_ps(dot8(e2_x, e2_y, e2_z, q_x, q_y, q_z), inverse_determinant);
  hit = _mm256_and_ps(hit, _mm256_and_ps(_mm256_cmp_ps(t, _mm256_set1_ps(ray.t_min), _CMP_GT_OQ),
                                         _mm256_cmp_ps(t, _mm256_set1_ps(ray.t_max), _CMP_LT_OQ)));
  _mm256_storeu_ps(t_hit, t);
  _mm256_storeu_ps(b1_hit, b1);
  _mm256_storeu_ps(b2_hit, b2);
  return static_cast<unsigned>(_mm256_movemask_ps(hit));
}

// FourAtATime (solutions/05_bvh/leaf_test.h) eight at a time: the same hit, bits and count.
struct EightAtATime {
  const std::uint32_t* primitive_order;
  TriangleColumns columns;
  TriangleHit* closest_triangle_hit;  // as FourAtATime's

  __attribute__((target("avx2"))) void operator()(Ray& search, std::uint32_t begin, std::uint32_t end, bool any_hit,
                                                  std::optional<BvhHit>& closest, std::uint64_t& tested) const {
    for (std::uint32_t first = begin; first < end; first += 8) {
      const std::uint32_t lanes = end - first < 8 ? end - first : 8;
      float t_hit[8], b1_hit[8], b2_hit[8];
      unsigned mask = moller_trumbore8(search, columns, first, t_hit, b1_hit, b2_hit) & ((1u << lanes) - 1u);
      if (mask == 0) {
        tested += lanes;
        continue;
      }
      int best = __builtin_ctz(mask);  // the first lane hit
      if (any_hit) {
        tested += static_cast<std::uint64_t>(best) + 1;
      } else {
        tested += lanes;
        for (unsigned others = mask & (mask - 1); others != 0; others &= others - 1) {
          const int lane = __builtin_ctz(others);
          if (t_hit[lane] < t_hit[best]) best = lane;
        }
      }
      search.t_max = t_hit[best];
      closest = BvhHit{t_hit[best], primitive_order[first + best]};
      if (closest_triangle_hit) *closest_triangle_hit = TriangleHit{t_hit[best], b1_hit[best], b2_hit[best]};
      if (any_hit) return;
    }
  }
};

// traverse4 (solutions/05c_wide_bvh/wide_bvh.cpp) over eight slots: the box test of
// box_slabs.h in eight lanes (entry and exit planes chosen once per ray by the direction's
// signs, the exit scaled up by 1 + 2 gamma(3)); a node's hit leaves tested nearest first, its
// nearest hit inner child visited next and the others pushed farthest first (the lowest slot
// first on a tie); a waiting node dropped once a closer hit is known. Compiled for AVX2 (the
// caller checks the CPU); the arithmetic is the SSE version's, lane for lane (no FMA). Made once
// for closest hits and once for any hit (shadow rays), without the query's branches.
template <bool any_hit, typename TestLeaf>
__attribute__((target("avx2"))) std::optional<BvhHit> traverse8(const Bvh8& bvh, const Ray& ray,
                                                                BvhTraversalStats& stats, const TestLeaf& test_leaf) {
  const glm::vec3 ray_direction_inverse = ray_direction_inverse_of(ray);
  __m256 origin[3], inverse[3];
  std::size_t entry_plane[3], exit_plane[3];
  const std::size_t lows[3] = {offsetof(Bvh8Node, min_x), offsetof(Bvh8Node, min_y), offsetof(Bvh8Node, min_z)};
  const std::size_t highs[3] = {offsetof(Bvh8Node, max_x), offsetof(Bvh8Node, max_y), offsetof(Bvh8Node, max_z)};
  for (int axis = 0; axis < 3; ++axis) {
    origin[axis] = _mm256_set1_ps(ray.origin[axis]);
    inverse[axis] = _mm256_set1_ps(ray_direction_inverse[axis]);
    const bool negative = ray_direction_inverse[axis] < 0.0f;
    entry_plane[axis] = negative ? highs[axis] : lows[axis];
    exit_plane[axis] = negative ? lows[axis] : highs[axis];
  }
  const __m256 widen = _mm256_set1_ps(1.0f + 2.0f * gamma_bound(3));
  const Bvh8Node* nodes = bvh.nodes.data();
  Ray search = ray;
  std::optional<BvhHit> closest;
  struct Waiting {
    std::uint32_t node;
    float t_enter;
  };
  // Each visit adds at most 8 - 1 waiting nodes, and the tree is no deeper than its binary tree.
  Waiting stack[8 * kBvhMaxDepth + 1];
  int stack_size = 0;
  Waiting next{0, ray.t_min};  // the node to visit next: the root first
  std::uint64_t nodes_visited = 0, primitives_tested = 0;
  for (;;) {
    if (!(next.t_enter > search.t_max)) {
      const Bvh8Node& node = nodes[next.node];
      const char* const bytes = reinterpret_cast<const char*>(&node);
      __m256 enter = _mm256_set1_ps(search.t_min), exit = _mm256_set1_ps(search.t_max);
      for (int axis = 0; axis < 3; ++axis) {
        const __m256 near_plane = _mm256_loadu_ps(reinterpret_cast<const float*>(bytes + entry_plane[axis]));
        const __m256 far_plane = _mm256_loadu_ps(reinterpret_cast<const float*>(bytes + exit_plane[axis]));
        const __m256 entry = _mm256_mul_ps(_mm256_sub_ps(near_plane, origin[axis]), inverse[axis]);
        const __m256 leave = _mm256_mul_ps(_mm256_mul_ps(_mm256_sub_ps(far_plane, origin[axis]), inverse[axis]), widen);
        enter = _mm256_max_ps(entry, enter);  // (a NaN entry leaves enter as it was, as _mm_max_ps)
        exit = _mm256_min_ps(leave, exit);
      }
      float entries[kBvh8Width];
      _mm256_storeu_ps(entries, enter);
      const unsigned used = (1u << node.child_count) - 1u;
      const unsigned mask = static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(enter, exit, _CMP_LE_OQ))) & used;
      ++nodes_visited;
      const unsigned leaves = mask & node.leaf_slots;
      for (unsigned waiting_leaves = leaves; waiting_leaves != 0;) {
        int nearest = __builtin_ctz(waiting_leaves);
        for (unsigned others = waiting_leaves & (waiting_leaves - 1); others != 0; others &= others - 1) {
          const int slot = __builtin_ctz(others);
          if (entries[slot] < entries[nearest]) nearest = slot;
        }
        waiting_leaves &= ~(1u << nearest);
        if (entries[nearest] > search.t_max) continue;
        test_leaf(search, node.child[nearest], node.child[nearest] + node.primitive_count[nearest], any_hit, closest,
                  primitives_tested);
        if (any_hit && closest) break;
      }
      if (any_hit && closest) break;
      unsigned inner = mask & ~leaves;
      if (inner != 0) {
        int order[kBvh8Width], count = 0;
        for (; inner != 0; inner &= inner - 1) {
          const int slot = __builtin_ctz(inner);
          const char* child = reinterpret_cast<const char*>(nodes + node.child[slot]);  // its boxes: 3 lines
          _mm_prefetch(child, _MM_HINT_T0);
          _mm_prefetch(child + 64, _MM_HINT_T0);
          _mm_prefetch(child + 128, _MM_HINT_T0);
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

// intersect_bvh4's answers and counts on the 8-wide tree, its triangles tested inlined: eight at
// a time when `triangles` has their columns (in the tree's leaf order), else one after another.
inline std::optional<BvhHit> intersect_bvh8_inlined(const Bvh8& bvh, const Ray& ray, const LeafTriangles& triangles,
                                                    bool any_hit, BvhTraversalStats& stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  if (triangles.columns.values) {
    const EightAtATime test_leaf{bvh.primitive_order.data(), triangles.columns, triangles.closest_triangle_hit};
    return any_hit ? traverse8<true>(bvh, ray, stats, test_leaf) : traverse8<false>(bvh, ray, stats, test_leaf);
  }
  return with_leaf_test(triangles, bvh.primitive_order.data(), [&](const auto& test_leaf) {
    return any_hit ? traverse8<true>(bvh, ray, stats, test_leaf) : traverse8<false>(bvh, ray, stats, test_leaf);
  });
}

// The same, a call of intersector.test per triangle (as a stage traversal).
inline std::optional<BvhHit> intersect_bvh8(const Bvh8& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                           bool any_hit, BvhTraversalStats& stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  return with_leaf_test(intersector, bvh.primitive_order.data(), [&](const auto& test_leaf) {
    return any_hit ? traverse8<true>(bvh, ray, stats, test_leaf) : traverse8<false>(bvh, ray, stats, test_leaf);
  });
}
#endif

}  // namespace raylab::reference
