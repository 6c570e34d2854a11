// The reference's fastest tree: stage 05c's 4-wide tree made 8 wide, its eight boxes tested
// at once with AVX2 where the CPU has it (chosen at run time: the default build assumes no more
// than SSE2). raylab-reference and bench/ trace it instead of the 4-wide tree
// (TracingFunctions::reference_tree in raylab/geometry.h); a leaf's triangles are tested four
// at a time as there (solutions/05_bvh/leaf_test.h). The same visit rule as
// solutions/05c_wide_bvh/wide_bvh.cpp's traverse4, and fewer nodes per ray. The same closest t,
// except that where a ray meets a vertex the triangles around it give t's an ulp apart and trees
// of other widths may prune between them (as the 4-wide tree already does against the binary
// one): the course scenes render to the same bits either way (tests/test_render.cpp). Not a
// stage and not part of any student contract; docs/performance.md measures it.
#pragma once

#include "../05_bvh/leaf_test.h"

#include "raylab/geometry.h"
#include "raylab/math.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

// GCC or Clang on x86; not MinGW's GCC, which cannot align a 32-byte vector on the stack of a
// Win64 function (GCC bug 54412) and could crash on the spilled __m256 values.
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__)) && \
    !(defined(_WIN32) && !defined(__clang__))
#include <immintrin.h>
#define RAYLAB_REFERENCE_WIDE8 1
#endif

namespace raylab::reference {

// Whether the 8-wide tree is traced on this machine (else the 4-wide one is).
inline bool eight_wide_tree_runs_here() {
#if RAYLAB_REFERENCE_WIDE8
  return __builtin_cpu_supports("avx2");  // (GCC's and Clang's check include the OS saving AVX state)
#else
  return false;
#endif
}

#if RAYLAB_REFERENCE_WIDE8
constexpr int kBvh8Width = 8;

// As Bvh4Node (raylab/stages/05c_wide_bvh.h), eight slots: 256 bytes, four cache lines.
struct alignas(64) Bvh8Node {
  float min_x[kBvh8Width], min_y[kBvh8Width], min_z[kBvh8Width];
  float max_x[kBvh8Width], max_y[kBvh8Width], max_z[kBvh8Width];
  std::uint32_t child[kBvh8Width];
  std::uint16_t primitive_count[kBvh8Width];
  std::uint8_t child_count = 0;
  std::uint8_t padding[15] = {};

  bool is_leaf(int slot) const { return primitive_count[slot] > 0; }
};
static_assert(sizeof(Bvh8Node) == 256, "a Bvh8Node is four cache lines");

struct Bvh8 {
  std::vector<Bvh8Node> nodes;
  std::vector<std::uint32_t> primitive_order;  // the binary tree's, unchanged
};

// As collapse_bvh4: open the inner child of largest surface area until there are eight.
inline std::uint32_t collapse_into_bvh8(const Bvh& binary, Bvh8& wide, std::uint32_t index) {
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
  if (node.is_leaf()) {
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
      if (child.is_leaf()) continue;
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
    if (child.is_leaf()) {
      wide.nodes[wide_index].child[i] = child.first_index;
      wide.nodes[wide_index].primitive_count[i] = static_cast<std::uint16_t>(child.primitive_count);
    } else {
      const std::uint32_t grandchild = collapse_into_bvh8(binary, wide, children[i]);
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
  collapse_into_bvh8(binary, wide, 0);
  return wide;
}

// traverse4 (solutions/05c_wide_bvh/wide_bvh.cpp) over eight slots: the box test of
// box_slabs.h in eight lanes (entry and exit planes chosen once per ray by the direction's
// signs, the exit scaled up by 1 + 2 gamma(3)); a node's hit leaves tested nearest first, its
// nearest hit inner child visited next and the others pushed farthest first (the lowest slot
// first on a tie); a waiting node dropped once a closer hit is known. Compiled for AVX2 (the
// caller checks the CPU); the arithmetic is the SSE version's, lane for lane (no FMA).
template <typename TestLeaf>
__attribute__((target("avx2"))) std::optional<BvhHit> traverse8(const Bvh8& bvh, const Ray& ray, bool any_hit,
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
      unsigned leaves = 0;
      for (unsigned bits = mask; bits != 0; bits &= bits - 1) {
        const int slot = __builtin_ctz(bits);
        if (node.is_leaf(slot)) leaves |= 1u << slot;
      }
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

// The functions of TracingFunctions::reference_tree.
inline std::shared_ptr<const void> build_bvh8_if_supported(const Bvh& binary) {
  if (binary.nodes.empty() || !eight_wide_tree_runs_here()) return nullptr;
  return std::make_shared<const Bvh8>(collapse_bvh8(binary));
}

inline std::optional<BvhHit> intersect_bvh8(const void* tree, const Ray& ray, const PrimitiveIntersector& intersector,
                                           bool any_hit, BvhTraversalStats& stats) {
  const Bvh8& bvh = *static_cast<const Bvh8*>(tree);
  return with_leaf_test(intersector, bvh.primitive_order.data(), [&](const auto& test_leaf) {
    return traverse8(bvh, ray, any_hit, stats, test_leaf);
  });
}
#endif

// What raylab-reference and bench/ hand the renderer: the 8-wide tree, or nullptr where this
// compiler or CPU family has none (then the 4-wide tree is traced).
inline const ReferenceTreeFunctions* reference_tree_functions() {
#if RAYLAB_REFERENCE_WIDE8
  static const ReferenceTreeFunctions functions{&build_bvh8_if_supported, &intersect_bvh8};
  return &functions;
#else
  return nullptr;
#endif
}

}  // namespace raylab::reference
