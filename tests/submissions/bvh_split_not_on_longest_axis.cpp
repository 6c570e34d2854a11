// Grader self-test submission (stage 05_bvh), broken: the root is not split along its longest
// axis. The reference's median build runs on the primitive boxes squashed a thousandfold along the
// root's longest axis (so it picks another axis there), and the node boxes are then fitted to the
// real primitive boxes again: a valid tree with the right hits, split on the wrong axis.
#define build_bvh reference_build_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef build_bvh

namespace raylab {
namespace {

// Fits node `index`'s box (and those below it) to the primitives' real boxes.
Bounds3 fit_boxes(Bvh& bvh, std::uint32_t index, const std::vector<Bounds3>& boxes) {
  const BvhNode node = bvh.nodes[index];
  Bounds3 box;
  if (node.is_leaf()) {
    for (std::uint32_t i = node.first_index; i < node.first_index + node.primitive_count; ++i)
      box.extend(boxes[bvh.primitive_order[i]]);
  } else {
    box.extend(fit_boxes(bvh, node.first_index, boxes));
    box.extend(fit_boxes(bvh, node.first_index + 1, boxes));
  }
  bvh.nodes[index].bounds = box;
  return box;
}

}  // namespace

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  Bounds3 all;
  for (const Bounds3& box : primitive_bounds) all.extend(box);
  const glm::vec3 extent = all.extent();
  const int longest = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  std::vector<Bounds3> squashed = primitive_bounds;
  for (Bounds3& box : squashed) {
    box.min[longest] *= 1e-3f;  // the mistake's cause: this axis looks short
    box.max[longest] *= 1e-3f;
  }
  Bvh bvh = reference_build_bvh(squashed, max_leaf_size);
  if (!bvh.nodes.empty()) fit_boxes(bvh, 0, primitive_bounds);
  return bvh;
}

}  // namespace raylab
