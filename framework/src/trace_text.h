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

// A primitive test's answer in words: its t, and a triangle's barycentrics.
inline std::string t_text(const Words& words, const std::optional<float>& t) {
  return t ? words("hit at t = ", "在 t = ") + text(*t) + words("", " 处击中") : words("no hit", "没有击中");
}
inline std::string triangle_hit_text(const Words& words, const std::optional<TriangleHit>& hit) {
  return hit ? t_text(words, hit->t_hit) + words(", b1 = ", "，b1 = ") + text(hit->barycentric_b1) +
                   words(", b2 = ", "，b2 = ") + text(hit->barycentric_b2)
             : words("no hit", "没有击中");
}
// A sphere test's call, and a triangle test's, as the steps show them.
inline std::string sphere_call_text(const Words& words, const Sphere& sphere, std::size_t index) {
  return "intersect_ray_sphere(ray, " + words("center ", "球心 ") + text(sphere.center) + ", " +
         words("radius ", "半径 ") + text(sphere.radius) + ")   [" + words("sphere ", "球 ") + std::to_string(index) +
         "]";
}
// (`mesh`: the mesh as the steps name it, by its name in quotes, else its index)
inline std::string triangle_call_text(const Words& words, const glm::vec3& p0, const glm::vec3& p1,
                                      const glm::vec3& p2, std::size_t triangle, const std::string& mesh) {
  return "intersect_ray_triangle(ray, " + text(p0) + ", " + text(p1) + ", " + text(p2) + ")   [" +
         words("triangle " + std::to_string(triangle) + " of mesh " + mesh,
               "网格 " + mesh + " 的三角形 " + std::to_string(triangle)) +
         "]";
}
inline std::string mesh_text(const Scene& scene, std::size_t m) {
  return scene.meshes[m].name.empty() ? std::to_string(m) : "\"" + scene.meshes[m].name + "\"";
}
// Each triangle of the scene's meshes in turn: visit(mesh index, triangle index, p0, p1, p2).
template <typename Visit>
void for_each_triangle(const Scene& scene, const Visit& visit) {
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    for (std::size_t k = 0; k < mesh.triangle_count(); ++k)
      visit(m, k, mesh.positions[mesh.indices[3 * k]], mesh.positions[mesh.indices[3 * k + 1]],
            mesh.positions[mesh.indices[3 * k + 2]]);
  }
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
