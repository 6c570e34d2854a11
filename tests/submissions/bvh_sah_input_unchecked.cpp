// Grader self-test submission (stage 05b_bvh_sah): the SAH build without build_bvh's two input
// checks: no primitives give a root holding nothing (not an empty Bvh), and a max_leaf_size above
// kBvhMaxLeafSize is clamped instead of throwing std::invalid_argument. The reference's SAH build
// is included under another name; build_bvh (stage 05) stays the reference's.
#define build_bvh_sah reference_build_bvh_sah
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh_sah

#include <algorithm>

namespace raylab {

Bvh build_bvh_sah(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  if (primitive_bounds.empty()) {
    Bvh bvh;
    bvh.nodes.push_back(BvhNode{});  // the first mistake: a root with nothing in it
    return bvh;
  }
  return reference_build_bvh_sah(primitive_bounds, std::clamp(max_leaf_size, 1, kBvhMaxLeafSize));  // the second
}

}  // namespace raylab
