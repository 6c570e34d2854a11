// Grader self-test submission (stage 05b_bvh_sah), broken: build_bvh_sah returns the median build
// (a valid tree, but its SAH cost is far above a SAH build's). The reference's builds are included
// under other names.
#define build_bvh_sah reference_build_bvh_sah
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh_sah

namespace raylab {

Bvh build_bvh_sah(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  return build_bvh(primitive_bounds, max_leaf_size);
}

}  // namespace raylab
