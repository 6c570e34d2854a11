// Grader self-test submission (stage 05_bvh): the reference tree, but the node array is
// sized up front to 2N - 1 nodes, with 0xFFFFFFFF ("no index") in every node the build
// does not use. Those nodes are never reached from the root: a broken tree. Reading it must
// not crash the grader (first_index + 1 wraps around to 0 in 32 bits); expected: the
// invariant failure "is never reached from the root", and the picture lost (the renderer
// refuses the tree).
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh

namespace raylab {

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  Bvh bvh = reference_build_bvh(primitive_bounds, max_leaf_size);
  if (primitive_bounds.empty()) return bvh;
  BvhNode unused;
  unused.first_index = 0xFFFFFFFFu;
  unused.primitive_count = 0;
  bvh.nodes.resize(2 * primitive_bounds.size() - 1, unused);
  return bvh;
}

}  // namespace raylab
