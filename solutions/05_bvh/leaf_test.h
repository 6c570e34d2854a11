// How the reference traversals (solutions/05_bvh/bvh.cpp, solutions/05c_wide_bvh/wide_bvh.cpp)
// test a leaf's primitives. As the stage contract says, by a call of intersector.test each. And
// for the reference's own trees over a scene's triangles (solutions/05c_wide_bvh/fast_tree.h)
// and bench/, which hold the triangles themselves (LeafTriangles below): with the reference's
// own Moller-Trumbore (moller_trumbore.h, the same source as its stage 03) inlined, and with
// their columns in leaf order, four triangles at a time with SSE, the same operations in the
// same order in each lane. Every way gives the same hit, the same bits of t (and of the
// barycentrics, where the inlined tests hand them to LeafTriangles::closest_triangle_hit) and
// the same count of triangles tested. Not part of any student contract.
#pragma once

#include "../03_triangle/moller_trumbore.h"

#include "raylab/stages/05_bvh.h"
#include "raylab/stages/05c_wide_bvh.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#if defined(__SSE2__) || defined(_M_X64)
#include <xmmintrin.h>
#define RAYLAB_REFERENCE_LEAF_SSE 1
#endif

namespace raylab::reference {

// One triangle as the inlined test takes it: its first vertex and its two edges from there,
// p1 - p0 and p2 - p0.
struct TriangleEdges {
  glm::vec3 p0{0.0f}, edge_01{0.0f}, edge_02{0.0f};

  static TriangleEdges of(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
    return {p0, p1 - p0, p2 - p0};
  }
};

// The same triangles as nine columns of floats (p0.x, p0.y, p0.z, edge_01.x, ... edge_02.z),
// in the order of a tree's primitive_order: column c of the triangle at position i is
// values[c * stride + i], and each column ends with 7 values of padding, so that a leaf test
// loads four or eight neighbours' coordinates at once (triangle_columns() makes them).
struct TriangleColumns {
  const float* values = nullptr;
  std::size_t stride = 0;

  // The columns that triangle_columns() made (nine of `stride` values each).
  // It points into `made`, which must outlive it (hence no temporaries).
  static TriangleColumns of(const std::vector<float>& made) { return {made.data(), made.size() / 9}; }
  static TriangleColumns of(std::vector<float>&&) = delete;
};

// The columns of triangles[primitive_order[i]] for every position i, padded: their stride is
// primitive_order.size() + 7 (TriangleColumns::of takes it from them).
inline std::vector<float> triangle_columns(const TriangleEdges* triangles,
                                           const std::vector<std::uint32_t>& primitive_order) {
  const std::size_t stride = primitive_order.size() + 7;
  std::vector<float> values(9 * stride, 0.0f);
  for (std::size_t i = 0; i < primitive_order.size(); ++i) {
    const TriangleEdges& triangle = triangles[primitive_order[i]];
    for (int axis = 0; axis < 3; ++axis) {
      values[(0 + axis) * stride + i] = triangle.p0[axis];
      values[(3 + axis) * stride + i] = triangle.edge_01[axis];
      values[(6 + axis) * stride + i] = triangle.edge_02[axis];
    }
  }
  return values;
}

// The triangles a tree's leaves hold, for the inlined tests: triangles[primitive] is the
// triangle of the caller's index `primitive` (a value of primitive_order); optionally their
// columns in the tree's leaf order (tested four at a time), and where the t and barycentrics
// of each closer hit found go.
struct LeafTriangles {
  const TriangleEdges* triangles = nullptr;
  TriangleColumns columns = {};
  TriangleHit* closest_triangle_hit = nullptr;
};

// A leaf's test, as the traversals call it: the primitives at positions [begin, end) of
// primitive_order, in that order; each hit in (search.t_min, search.t_max) lowers
// search.t_max and becomes `closest`; any_hit: stop at the first. Adds the primitives tested
// to `tested`.
template <typename TestPrimitive>
struct OneAfterAnother {
  const std::uint32_t* primitive_order;
  TestPrimitive test_primitive;  // (search, primitive) -> t or nullopt, as intersector.test

  void operator()(Ray& search, std::uint32_t begin, std::uint32_t end, bool any_hit,
                  std::optional<BvhHit>& closest, std::uint64_t& tested) const {
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t primitive = primitive_order[i];
      ++tested;
      if (const std::optional<float> t = test_primitive(search, primitive)) {
        search.t_max = *t;
        closest = BvhHit{*t, primitive};
        if (any_hit) return;
      }
    }
  }
};

#if RAYLAB_REFERENCE_LEAF_SSE
// moller_trumbore() in four lanes: the triangles at positions [first, first + 4) of the
// columns. Returns the mask of the lanes hit in (ray.t_min, ray.t_max), their t and
// barycentrics in t_hit, b1 and b2.
inline unsigned moller_trumbore4(const Ray& ray, const TriangleColumns& columns, std::uint32_t first,
                                 float t_hit[4], float b1_hit[4], float b2_hit[4]) {
  const auto column = [&](int c) { return _mm_loadu_ps(columns.values + c * columns.stride + first); };
  const __m128 p0_x = column(0), p0_y = column(1), p0_z = column(2);
  const __m128 e1_x = column(3), e1_y = column(4), e1_z = column(5);
  const __m128 e2_x = column(6), e2_y = column(7), e2_z = column(8);
  const __m128 d_x = _mm_set1_ps(ray.direction.x), d_y = _mm_set1_ps(ray.direction.y),
               d_z = _mm_set1_ps(ray.direction.z);
  const auto dot = [](__m128 ax, __m128 ay, __m128 az, __m128 bx, __m128 by, __m128 bz) {  // (x + y) + z, as glm
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, bx), _mm_mul_ps(ay, by)), _mm_mul_ps(az, bz));
  };
  // glm::cross(direction, edge_02)
  const __m128 c_x = _mm_sub_ps(_mm_mul_ps(d_y, e2_z), _mm_mul_ps(e2_y, d_z));
  const __m128 c_y = _mm_sub_ps(_mm_mul_ps(d_z, e2_x), _mm_mul_ps(e2_z, d_x));
  const __m128 c_z = _mm_sub_ps(_mm_mul_ps(d_x, e2_y), _mm_mul_ps(e2_x, d_y));
  const __m128 determinant = dot(e1_x, e1_y, e1_z, c_x, c_y, c_z);
  // != 0 (true for NaN, as in C++) and finite: |determinant| < infinity (false for NaN).
  const __m128 absolute = _mm_andnot_ps(_mm_set1_ps(-0.0f), determinant);
  __m128 hit = _mm_and_ps(_mm_cmpneq_ps(determinant, _mm_setzero_ps()),
                          _mm_cmplt_ps(absolute, _mm_set1_ps(std::numeric_limits<float>::infinity())));
  const __m128 inverse_determinant = _mm_div_ps(_mm_set1_ps(1.0f), determinant);
  const __m128 o_x = _mm_sub_ps(_mm_set1_ps(ray.origin.x), p0_x), o_y = _mm_sub_ps(_mm_set1_ps(ray.origin.y), p0_y),
               o_z = _mm_sub_ps(_mm_set1_ps(ray.origin.z), p0_z);
  const __m128 b1 = _mm_mul_ps(dot(o_x, o_y, o_z, c_x, c_y, c_z), inverse_determinant);
  hit = _mm_and_ps(hit, _mm_and_ps(_mm_cmpge_ps(b1, _mm_setzero_ps()), _mm_cmple_ps(b1, _mm_set1_ps(1.0f))));
  // glm::cross(p0_to_origin, edge_01)
  const __m128 q_x = _mm_sub_ps(_mm_mul_ps(o_y, e1_z), _mm_mul_ps(e1_y, o_z));
  const __m128 q_y = _mm_sub_ps(_mm_mul_ps(o_z, e1_x), _mm_mul_ps(e1_z, o_x));
  const __m128 q_z = _mm_sub_ps(_mm_mul_ps(o_x, e1_y), _mm_mul_ps(e1_x, o_y));
  const __m128 b2 = _mm_mul_ps(dot(d_x, d_y, d_z, q_x, q_y, q_z), inverse_determinant);
  hit = _mm_and_ps(hit, _mm_and_ps(_mm_cmpge_ps(b2, _mm_setzero_ps()),
                                   _mm_cmple_ps(_mm_add_ps(b1, b2), _mm_set1_ps(1.0f))));
  const __m128 t = _mm_mul_ps(dot(e2_x, e2_y, e2_z, q_x, q_y, q_z), inverse_determinant);
  hit = _mm_and_ps(hit, _mm_and_ps(_mm_cmpgt_ps(t, _mm_set1_ps(ray.t_min)), _mm_cmplt_ps(t, _mm_set1_ps(ray.t_max))));
  _mm_storeu_ps(t_hit, t);
  _mm_storeu_ps(b1_hit, b1);
  _mm_storeu_ps(b2_hit, b2);
  return static_cast<unsigned>(_mm_movemask_ps(hit));
}
#endif

// OneAfterAnother's answers, four triangles at a time. Testing one after another, each hit
// lowers t_max for the next: the result is the first of the triangles with the smallest t
// below the t_max at the start, and the count is every triangle (any hit: up to the first
// hit). Four lanes against the same t_max give exactly that.
struct FourAtATime {
  const std::uint32_t* primitive_order;
  TriangleColumns columns;
  TriangleHit* closest_triangle_hit;  // LeafTriangles::closest_triangle_hit: nullptr or where each closer hit goes

  void operator()(Ray& search, std::uint32_t begin, std::uint32_t end, bool any_hit,
                  std::optional<BvhHit>& closest, std::uint64_t& tested) const {
#if RAYLAB_REFERENCE_LEAF_SSE
    for (std::uint32_t first = begin; first < end; first += 4) {
      const std::uint32_t lanes = end - first < 4 ? end - first : 4;
      float t_hit[4], b1_hit[4], b2_hit[4];
      unsigned mask = moller_trumbore4(search, columns, first, t_hit, b1_hit, b2_hit) & ((1u << lanes) - 1u);
      if (mask == 0) {
        tested += lanes;
        continue;
      }
      int best = 0;
      while (!(mask & (1u << best))) ++best;  // the first lane hit
      if (any_hit) {
        tested += static_cast<std::uint64_t>(best) + 1;
      } else {
        tested += lanes;
        for (int lane = best + 1; lane < 4; ++lane)
          if ((mask & (1u << lane)) && t_hit[lane] < t_hit[best]) best = lane;
      }
      search.t_max = t_hit[best];
      closest = BvhHit{t_hit[best], primitive_order[first + best]};
      if (closest_triangle_hit) *closest_triangle_hit = TriangleHit{t_hit[best], b1_hit[best], b2_hit[best]};
      if (any_hit) return;
    }
#else
    (void)search, (void)begin, (void)end, (void)any_hit, (void)closest, (void)tested;
#endif
  }
};

// traverse(test_leaf) with the fastest leaf test `triangles` allow (see above).
template <typename Traverse>
std::optional<BvhHit> with_leaf_test(const LeafTriangles& leaf_triangles, const std::uint32_t* primitive_order,
                                     const Traverse& traverse) {
#if RAYLAB_REFERENCE_LEAF_SSE
  if (leaf_triangles.columns.values)
    return traverse(FourAtATime{primitive_order, leaf_triangles.columns, leaf_triangles.closest_triangle_hit});
#endif
  // (Every hit a leaf test returns lowers search.t_max: each is closer than the one before.)
  const auto test = [triangles = leaf_triangles.triangles,
                     closest_triangle_hit = leaf_triangles.closest_triangle_hit](const Ray& search,
                                                                                std::uint32_t primitive) {
    const TriangleEdges& triangle = triangles[primitive];
    TriangleHit hit;
    if (!moller_trumbore(search, triangle.p0, triangle.edge_01, triangle.edge_02, hit)) return std::optional<float>();
    if (closest_triangle_hit) *closest_triangle_hit = hit;
    return std::optional<float>(hit.t_hit);
  };
  return traverse(OneAfterAnother<decltype(test)>{primitive_order, test});
}

// traverse(test_leaf) with a call of intersector.test per primitive, as the contract says.
template <typename Traverse>
std::optional<BvhHit> with_leaf_test(const PrimitiveIntersector& intersector, const std::uint32_t* primitive_order,
                                     const Traverse& traverse) {
  const auto test = [&intersector](const Ray& search, std::uint32_t primitive) {
    return intersector.test(intersector.context, search, primitive);
  };
  return traverse(OneAfterAnother<decltype(test)>{primitive_order, test});
}

// intersect_bvh (solutions/05_bvh/bvh.cpp) and intersect_bvh4 (solutions/05c_wide_bvh/
// wide_bvh.cpp) with the triangles tested inlined: the same hits and counts.
std::optional<BvhHit> intersect_bvh_inlined(const Bvh& bvh, const Ray& ray, const LeafTriangles& triangles,
                                            bool any_hit, BvhTraversalStats& stats);
std::optional<BvhHit> intersect_bvh4_inlined(const Bvh4& bvh, const Ray& ray, const LeafTriangles& triangles,
                                             bool any_hit, BvhTraversalStats& stats);

}  // namespace raylab::reference
