// Grader self-test submission (stage 05_bvh): mistake: the median build splits every node down
// to one primitive, whatever max_leaf_size says. A valid tree with the right hits, but the
// contract splits only a node holding more than max_leaf_size primitives: expected, only the
// median-split test fails, and its hint says so.
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh

namespace raylab {

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  if (max_leaf_size < 1 || max_leaf_size > kBvhMaxLeafSize) throw std::invalid_argument("build_bvh: bad max_leaf_size");
  return reference_build_bvh(primitive_bounds, 1);
}

}  // namespace raylab
