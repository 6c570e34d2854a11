// Grader self-test submission (stage 05_bvh), broken: primitive_order names its first primitive
// twice (at the end too), so the last primitive is in no leaf.
// The reference's build is included under another name and its tree changed afterwards.
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh

namespace raylab {

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  Bvh bvh = reference_build_bvh(primitive_bounds, max_leaf_size);
  if (bvh.primitive_order.size() > 1) bvh.primitive_order.back() = bvh.primitive_order.front();
  return bvh;
}

}  // namespace raylab
