// Grader self-test submission (stage 05_bvh), broken: the root's two children swapped, so its first
// child holds the larger centroids along split_axis (a valid tree with the right hits, but a
// traversal that enters the first child for a ray going towards +split_axis enters the far one).
// The reference's build is included under another name and its tree changed afterwards.
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh

#include <utility>

namespace raylab {

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  Bvh bvh = reference_build_bvh(primitive_bounds, max_leaf_size);
  if (bvh.nodes.size() >= 3 && !bvh.nodes[0].is_leaf()) {
    const std::uint32_t first = bvh.nodes[0].first_index;
    std::swap(bvh.nodes[first], bvh.nodes[first + 1]);  // the mistake (each keeps its own subtree)
  }
  return bvh;
}

}  // namespace raylab
