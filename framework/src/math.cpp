#include "raylab/math.h"
#include "raylab/ray.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/stages/07_sampling.h"

#include <iomanip>
#include <limits>

namespace glm {

std::ostream& operator<<(std::ostream& out, const vec2& v) {
  const auto old_precision = out.precision(std::numeric_limits<float>::max_digits10);
  out << '(' << v.x << ", " << v.y << ')';
  out.precision(old_precision);
  return out;
}

std::ostream& operator<<(std::ostream& out, const vec3& v) {
  const auto old_precision = out.precision(std::numeric_limits<float>::max_digits10);
  out << '(' << v.x << ", " << v.y << ", " << v.z << ')';
  out.precision(old_precision);
  return out;
}

}  // namespace glm

namespace raylab {

std::ostream& operator<<(std::ostream& out, const Ray& ray) {
  return out << "origin " << ray.origin << " direction " << ray.direction << " t in ("
             << ray.t_min << ", " << ray.t_max << ')';
}

std::ostream& operator<<(std::ostream& out, const TriangleHit& hit) {
  return out << "t_hit " << hit.t_hit << " b1 " << hit.barycentric_b1 << " b2 "
             << hit.barycentric_b2;
}

std::ostream& operator<<(std::ostream& out, const Barycentrics& barycentrics) {
  return out << "b1 " << barycentrics.barycentric_b1 << " b2 " << barycentrics.barycentric_b2;
}

}  // namespace raylab
