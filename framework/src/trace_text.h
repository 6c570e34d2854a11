// raylab trace's helpers (trace.cpp, trace_monte_carlo.cpp, trace_whitted.cpp): values as the trace prints them,
// agreement within rounding, and a stage call that may be a stub.
#pragma once

#include "raylab/error.h"
#include "raylab/geometry.h"
#include "raylab/ray.h"
#include "raylab/scene.h"
#include "raylab/stages/03_triangle.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>

namespace raylab {
// How long a ray that hits nothing is drawn (TraceSegment): the diagonal of the box around the
// scene and its camera (trace.cpp).
float miss_length(const Scene& scene);
}  // namespace raylab

namespace raylab::trace_text {

inline std::string text(double v) {
  std::ostringstream out;
  out << std::setprecision(7) << v;
  return out.str();
}
inline std::string text(const glm::vec3& v) { return "(" + text(v.x) + ", " + text(v.y) + ", " + text(v.z) + ")"; }
inline std::string text(const glm::dvec3& v) { return "(" + text(v.x) + ", " + text(v.y) + ", " + text(v.z) + ")"; }
inline std::string text(const glm::vec2& v) { return "(" + text(v.x) + ", " + text(v.y) + ")"; }

// The words of a text in the trace's language (TraceSettings::chinese): values, code and the
// names of functions are the same in both.
struct Words {
  bool chinese = false;
  std::string operator()(const std::string& english, const std::string& chinese_text) const {
    return chinese ? chinese_text : english;
  }
};

// A ray in words.
inline std::string ray_text(const Words& words, const Ray& ray) {
  return words("origin ", "起点 ") + text(ray.origin) + words("  direction ", "  方向 ") + text(ray.direction);
}

// A hit's material in words, and a ray's closest hit (or the background).
inline std::string material_text(const Words& words, const Scene& scene, const SurfaceHit& hit) {
  const Material& material = scene.materials[hit.material];
  return material.name.empty() ? words("material ", "材质 ") + std::to_string(hit.material)
                               : words("material '", "材质 '") + material.name + "'";
}
inline std::string hit_text(const Words& words, const Scene& scene, const std::optional<SurfaceHit>& hit) {
  if (!hit) return words("nothing: the background", "什么也没有击中：背景");
  return words("hit at t = ", "在 t = ") + text(hit->t_hit) + words(", point ", " 处击中，交点 ") + text(hit->point) +
         words(", ", "，") + material_text(words, scene, *hit);
}
// A shadow ray's answer in words.
inline std::string blocked_text(const Words& words, bool blocked) {
  return blocked ? words("blocked", "被遮挡") : words("clear", "没有被遮挡");
}
// What a shadow ray's answer that is not the contract's means, when the ray itself is right.
inline std::string shadow_answer_note(const Words& words) {
  return words("your geometry (stages 02-05) answers this shadow ray otherwise than the contract's exact tests",
               "你的几何（阶段 02-05）对这条阴影光线的回答与契约的精确测试不同");
}
// What a bounce or secondary ray's closest hit that is not the contract's means.
inline std::string another_hit_note(const Words& words) {
  return words("your geometry (stages 02-05: spheres, triangles, boxes, trees) finds another hit",
               "你的几何（阶段 02-05：球、三角形、包围盒、树）找到了另一个交点");
}

// Agreement within float rounding: relative `relative` of the larger magnitude, or 1e-5 near 0.
inline bool near(double a, double b, double relative = 1e-4) {
  if (!std::isfinite(a) || !std::isfinite(b)) return a == b;
  return std::fabs(a - b) <= relative * std::max(std::fabs(a), std::fabs(b)) + 1e-5;
}
inline bool near(const glm::vec3& a, const glm::vec3& b, double relative = 1e-4) {
  return near(a.x, b.x, relative) && near(a.y, b.y, relative) && near(a.z, b.z, relative);
}
inline bool near(const glm::dvec3& a, const glm::dvec3& b, double relative = 1e-4) {
  return near(a.x, b.x, relative) && near(a.y, b.y, relative) && near(a.z, b.z, relative);
}
inline bool near(const std::optional<float>& a, const std::optional<float>& b) {
  return a.has_value() == b.has_value() && (!a || near(*a, *b));
}
// Barycentrics lie in [0, 1] and a float test rounds them by up to about 1e-4 where the ray meets
// the triangle's plane at a grazing angle: they agree within 1e-4 (a mistake, b1 and b2 swapped or
// left unnormalised, differs far more).
inline bool near(const std::optional<TriangleHit>& a, const std::optional<TriangleHit>& b) {
  return a.has_value() == b.has_value() &&
         (!a || (near(a->t_hit, b->t_hit) && std::fabs(a->barycentric_b1 - b->barycentric_b1) <= 1e-4 &&
                 std::fabs(a->barycentric_b2 - b->barycentric_b2) <= 1e-4));
}

// Your geometry's closest hit is the contract's: both none, or the same t (within rounding) and
// material.
inline bool same_closest_hit(const std::optional<SurfaceHit>& yours, const std::optional<SurfaceHit>& expected) {
  return yours.has_value() == expected.has_value() &&
         (!expected || (near(yours->t_hit, expected->t_hit) && yours->material == expected->material));
}

// Your function's answer, or nullopt with `not_written` set when it is a stub.
template <typename Call>
auto yours(const Call& call, bool& not_written) -> std::optional<decltype(call())> {
  try {
    return call();
  } catch (const NotImplemented&) {
    not_written = true;
    return std::nullopt;
  }
}

}  // namespace raylab::trace_text
