// Grader self-test submission (stage 05_bvh), broken: the leaf that holds the last primitives
// starts one place later, so its range runs past the end of primitive_order.
// The reference's build is included under another name and its tree changed afterwards.
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh

namespace raylab {

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  Bvh bvh = reference_build_bvh(primitive_bounds, max_leaf_size);
  for (BvhNode& node : bvh.nodes)
    if (node.is_leaf() && node.first_index + node.primitive_count == bvh.primitive_order.size()) ++node.first_index;
  return bvh;
}

}  // namespace raylab
