// Vector math for raylab: GLM's float vectors, plus the few helpers the framework needs.
// Geometry is float (as in GAMES101 and Embree); tests compare against double references.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <ostream>

namespace raylab {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr float kPi = 3.14159265358979323846f;

inline float degrees_to_radians(float degrees) { return degrees * (kPi / 180.0f); }

// gamma(n) = n u / (1 - n u), u = machine epsilon / 2: the bound on the relative error of n
// successive float operations (Higham; pbrt-v4 section 6.8). Used for conservative offsets.
constexpr float gamma_bound(int n) {
  constexpr float unit_roundoff = std::numeric_limits<float>::epsilon() * 0.5f;
  return (static_cast<float>(n) * unit_roundoff) / (1.0f - static_cast<float>(n) * unit_roundoff);
}

inline bool is_finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace raylab

// Printing for failure messages: "(x, y, z)" with enough digits to round-trip a float.
namespace glm {
std::ostream& operator<<(std::ostream& out, const vec2& v);
std::ostream& operator<<(std::ostream& out, const vec3& v);
}  // namespace glm
