// Triangle tests over arrays of triangles, and the brute-force loop that every BVH check
// compares with: the autograder's BVH suites, the framework tests, the stress suite and the
// BVH bench use these instead of writing the loops again.
#pragma once

#include "raylab/ray.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/stages/05_bvh.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace raylab::testkit {

// A ray-triangle test with the stage 03 contract: intersect_ray_triangle, the watertight
// intersect_ray_triangle_watertight, or a baseline kernel.
using TriangleFunction = std::optional<TriangleHit> (*)(const Ray&, const glm::vec3&, const glm::vec3&,
                                                        const glm::vec3&);

// Triangles given by corner positions and indices (3 per triangle), tested with `function`.
// Both vectors must outlive the intersector made from it.
struct IndexedTriangles {
  const std::vector<glm::vec3>* positions = nullptr;
  const std::vector<std::uint32_t>* indices = nullptr;
  TriangleFunction function = nullptr;
};

// The PrimitiveIntersector test over IndexedTriangles (its context): t of triangle `triangle`.
std::optional<float> test_indexed_triangle(void* triangles, const Ray& ray, std::uint32_t triangle);

inline PrimitiveIntersector intersector_over(const IndexedTriangles& triangles) {
  return PrimitiveIntersector{&test_indexed_triangle, const_cast<IndexedTriangles*>(&triangles)};
}

// Every primitive 0 .. primitive_count - 1 in turn, t_max lowered to each hit (with any_hit,
// the first hit ends it): the closest hit, or the first. `test(ray, primitive)` returns the
// hit's t or nullopt. A template, so that a benchmark's test is inlined as in its own loop.
template <typename Test>
std::optional<BvhHit> brute_force_hit(std::uint32_t primitive_count, const Ray& ray, bool any_hit, Test&& test) {
  Ray search = ray;
  std::optional<BvhHit> best;
  for (std::uint32_t primitive = 0; primitive < primitive_count; ++primitive)
    if (const std::optional<float> t = test(static_cast<const Ray&>(search), primitive)) {
      search.t_max = *t;
      best = BvhHit{*t, primitive};
      if (any_hit) break;
    }
  return best;
}

// The same through a PrimitiveIntersector.
inline std::optional<BvhHit> brute_force_hit(const PrimitiveIntersector& intersector, std::uint32_t primitive_count,
                                             const Ray& ray, bool any_hit = false) {
  return brute_force_hit(primitive_count, ray, any_hit, [&](const Ray& search, std::uint32_t primitive) {
    return intersector.test(intersector.context, search, primitive);
  });
}

}  // namespace raylab::testkit
