// Grader self-test submission (stage 05_bvh), broken: no primitives give a tree of one empty leaf
// (a root node holding nothing) instead of an empty Bvh. The reference's build is included under
// another name.
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh

namespace raylab {

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  if (primitive_bounds.empty()) {
    Bvh bvh;
    bvh.nodes.push_back(BvhNode{});  // the mistake: a root with nothing in it
    return bvh;
  }
  return reference_build_bvh(primitive_bounds, max_leaf_size);
}

}  // namespace raylab
