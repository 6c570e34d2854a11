// Axis-aligned bounding boxes: the boxes of stage 04_box and the nodes of stage 05_bvh.
#pragma once

#include "raylab/math.h"

#include <ostream>

namespace raylab {

// The closed box {p : min <= p <= max, per axis}. The default box is EMPTY: min = +infinity,
// max = -infinity, so that growing it by any point or box gives exactly that point or box.
// 24 bytes (two glm::vec3), so that a BVH node with its box fits in 32.
struct Bounds3 {
  glm::vec3 min{kInfinity};
  glm::vec3 max{-kInfinity};

  Bounds3() = default;
  Bounds3(const glm::vec3& min_corner, const glm::vec3& max_corner) : min(min_corner), max(max_corner) {}

  // True when some axis has min > max (the default box). A flat box (min == max on an
  // axis) is NOT empty: a triangle in the plane z = 0 has one.
  bool is_empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }

  void extend(const glm::vec3& point) {
    min = glm::min(min, point);
    max = glm::max(max, point);
  }
  void extend(const Bounds3& other) {
    min = glm::min(min, other.min);
    max = glm::max(max, other.max);
  }

  glm::vec3 extent() const { return max - min; }  // the diagonal; negative when empty
  glm::vec3 centroid() const { return 0.5f * (min + max); }

  // Area of the six faces (0 for an empty box): the "surface area" of the SAH.
  float surface_area() const {
    if (is_empty()) return 0.0f;
    const glm::vec3 e = extent();
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }

  // The axis (0 = x, 1 = y, 2 = z) along which the box is widest; ties go to the lower axis.
  int longest_axis() const {
    const glm::vec3 e = extent();
    if (e.x >= e.y && e.x >= e.z) return 0;
    return e.y >= e.z ? 1 : 2;
  }

  bool contains(const glm::vec3& point) const {
    return point.x >= min.x && point.x <= max.x && point.y >= min.y && point.y <= max.y &&
           point.z >= min.z && point.z <= max.z;
  }
  bool contains(const Bounds3& other) const {
    return other.is_empty() || (contains(other.min) && contains(other.max));
  }
};

// The smallest box holding both.
inline Bounds3 bounds_union(Bounds3 a, const Bounds3& b) {
  a.extend(b);
  return a;
}
inline Bounds3 bounds_union(Bounds3 a, const glm::vec3& point) {
  a.extend(point);
  return a;
}

inline bool operator==(const Bounds3& a, const Bounds3& b) { return a.min == b.min && a.max == b.max; }
inline bool operator!=(const Bounds3& a, const Bounds3& b) { return !(a == b); }

// "[(min) .. (max)]", or "[empty]".
std::ostream& operator<<(std::ostream& out, const Bounds3& box);

}  // namespace raylab
