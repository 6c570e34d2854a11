// Lights, in the shape of pbrt-v4's Light::SampleLi / PDF_Li: from a point being shaded,
// sample a direction towards a light with the radiance arriving along it and its density
// in solid angle, and give that density for any direction.
//
// Two kinds:
//   point lights   from the scene's "lights" (intensity I in W/sr, or power: I = flux / 4 pi);
//                  a delta light: one direction, no density (is_delta, pdf 1 by convention).
//   area lights    every triangle of an object and every sphere whose material emits
//                  (Material::emission, radiance in W / (m^2 sr)) from its front: the side
//                  its geometric normal points to (a triangle's by winding, a sphere's out,
//                  or in when it faces inward);
//                  sampled uniformly by area, the density turned into solid angle:
//                  pdf_solid_angle = pdf_area * distance^2 / |cos theta_light| (stage 08's
//                  area_pdf_to_solid_angle).
// A scene without point lights and without emitters has an empty LightSet: no light
// sampling, no shadow rays.
#pragma once

#include "raylab/math.h"
#include "raylab/scene.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace raylab {

enum class LightKind : std::uint8_t { Point, Triangle, Sphere };

struct Light {
  LightKind kind = LightKind::Point;
  glm::vec3 position{0.0f};   // Point: where it is
  glm::vec3 intensity{0.0f};  // Point: W/sr
  glm::vec3 p0{0.0f}, p1{0.0f}, p2{0.0f};  // Triangle: its corners, world space
  glm::vec3 normal{0.0f};  // Triangle: triangle_normal(p0, p1, p2); LightSet sets it (a Light made by hand must too)
  Sphere sphere;                         // Sphere
  glm::vec3 radiance{0.0f};  // Triangle and Sphere: emitted radiance
  float area = 0.0f;         // Triangle and Sphere
};

struct LightSample {
  glm::vec3 radiance{0.0f};   // arriving at the reference point, before any occlusion
  glm::vec3 direction{0.0f};  // unit, from the reference point towards the light point
  float distance = 0.0f;      // from the reference point to the light point
  float pdf = 0.0f;           // density of `direction` in solid angle (1 for a delta light)
  bool is_delta = false;      // a point light: only this direction, pdf_li gives 0
  glm::vec3 point{0.0f};      // on the light
};

// u in [0, 1)^2. nullopt when the sample cannot contribute: the reference point on the
// light, a light seen exactly edge-on or from its back, a zero-area shape. The density is
// that of sampling the whole shape, back included (pdf_li agrees).
std::optional<LightSample> sample_li(const Light& light, const glm::vec3& reference_point, glm::vec2 u);

// The solid-angle density with which sample_li(light, reference_point, .) gives the unit
// direction `direction`: 0 for a point light and for directions that miss the light.
float pdf_li(const Light& light, const glm::vec3& reference_point, const glm::vec3& direction);

// The flux a light emits (W per channel): 4 pi I for a point light, pi L A for an area
// light. For choosing lights by power.
glm::vec3 light_power(const Light& light);

// Every light of a scene: its point lights, then an area light per emissive triangle and
// sphere. A light is chosen uniformly (probability 1 / size()).
class LightSet {
 public:
  explicit LightSet(const Scene& scene);

  bool empty() const { return lights_.empty(); }
  std::size_t size() const { return lights_.size(); }
  const Light& operator[](std::size_t i) const { return lights_[i]; }
  const std::vector<Light>& lights() const { return lights_; }

  // The light for u in [0, 1), and the probability of choosing it. Requires !empty().
  std::size_t choose(float u, float* probability) const;

  // The solid-angle density with which one light sample (a light chosen by choose(), then
  // sample_li on it) gives the unit `direction` from `reference_point`: the sum over the lights
  // of (probability of choosing it) * pdf_li. 0 when no light lies along `direction` (and for
  // point lights, which no direction hits). For multiple importance sampling (stage 09b).
  float pdf_li(const glm::vec3& reference_point, const glm::vec3& direction) const;

 private:
  std::vector<Light> lights_;
};

}  // namespace raylab
