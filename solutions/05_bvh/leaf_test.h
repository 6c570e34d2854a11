// How the reference traversals (solutions/05_bvh/bvh.cpp, solutions/05c_wide_bvh/wide_bvh.cpp)
// test a leaf's primitives: with the reference's own Moller-Trumbore (moller_trumbore.h, the
// same source as its stage 03) inlined, when the renderer hands over the mesh's triangles
// (PrimitiveIntersector::triangles), else by a call of intersector.test each. Same hits, same
// bits. Not part of any student contract.
#pragma once

#include "../03_triangle/moller_trumbore.h"

#include "raylab/stages/05_bvh.h"

#include <optional>

namespace raylab::reference {

// traverse(test_primitive) with the leaf test to inline: test_primitive(search, primitive)
// returns the hit's t or nullopt, as intersector.test does.
template <typename Traverse>
std::optional<BvhHit> with_leaf_test(const PrimitiveIntersector& intersector, const Traverse& traverse) {
  if (const TriangleEdges* triangles = intersector.triangles) {
    return traverse([triangles](const Ray& search, std::uint32_t primitive) {
      const TriangleEdges& triangle = triangles[primitive];
      TriangleHit hit;
      return moller_trumbore(search, triangle.p0, triangle.edge_01, triangle.edge_02, hit)
                 ? std::optional<float>(hit.t_hit)
                 : std::nullopt;
    });
  }
  return traverse([&intersector](const Ray& search, std::uint32_t primitive) {
    return intersector.test(intersector.context, search, primitive);
  });
}

}  // namespace raylab::reference
