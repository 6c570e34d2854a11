// Grader self-test submission (stage 05_bvh), broken: max_leaf_size is never checked; one above
// kBvhMaxLeafSize is clamped to it instead of throwing std::invalid_argument as the contract says.
// The reference's build is included under another name.
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh

#include <algorithm>

namespace raylab {

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  return reference_build_bvh(primitive_bounds, std::clamp(max_leaf_size, 1, kBvhMaxLeafSize));  // the mistake
}

}  // namespace raylab
