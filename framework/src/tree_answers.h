// How a tree's answers are held against those of testing every primitive, the same way by
// SceneGeometry's choice of the best tree (geometry_build.cpp, --accel best) and by raylab bench's
// wrong-answers column (tree_bench.cpp). Private to framework/src.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

namespace raylab {

// Whether a tree's closest hit is that of testing every primitive: both none, or the same t
// within a millionth (relative above t = 1): a tree may reach the same surface through another
// of the triangles that share an edge or a vertex there, a rounding step away.
inline bool same_closest_t(std::optional<float> tree, std::optional<float> every_primitive) {
  return tree.has_value() == every_primitive.has_value() &&
         (!tree || std::fabs(*tree - *every_primitive) <= 1e-6f * std::max(1.0f, *every_primitive));
}

}  // namespace raylab
