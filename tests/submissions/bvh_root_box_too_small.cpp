// Grader self-test submission (stage 05_bvh), broken: the root's box is shrunk by a quarter of its
// size on x, so it no longer holds every primitive below it.
// The reference's build is included under another name and its tree changed afterwards.
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh

namespace raylab {

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  Bvh bvh = reference_build_bvh(primitive_bounds, max_leaf_size);
  if (!bvh.nodes.empty()) {
    Bounds3& root = bvh.nodes[0].bounds;
    root.max.x -= 0.25f * (root.max.x - root.min.x);
  }
  return bvh;
}

}  // namespace raylab
