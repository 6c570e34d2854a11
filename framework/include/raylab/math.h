// Vector math for raylab: GLM's float vectors, plus the few helpers the framework needs.
// Geometry is float (as in GAMES101 and Embree); tests compare against double references.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
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

// The next float above (below) v: std::nextafter(v, +infinity) (-infinity), without the call into
// the maths library (pbrt-v4's NextFloatUp): a finite float's neighbours are its bit pattern plus
// or minus one. Infinities towards themselves and NaN stay as they are; -0 and +0 both step to
// the smallest denormal.
inline float next_float_up(float v) {
  if (std::isnan(v) || v == kInfinity) return v;
  if (v == 0.0f) return std::numeric_limits<float>::denorm_min();
  std::uint32_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  bits = v > 0.0f ? bits + 1u : bits - 1u;
  std::memcpy(&v, &bits, sizeof bits);
  return v;
}
inline float next_float_down(float v) { return -next_float_up(-v); }

inline bool is_finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace raylab

// Printing for failure messages: "(x, y, z)" with enough digits to round-trip a float.
namespace glm {
std::ostream& operator<<(std::ostream& out, const vec2& v);
std::ostream& operator<<(std::ostream& out, const vec3& v);
}  // namespace glm
