#include "raylab/lights.h"

#include "raylab/shapes.h"
#include "raylab/stages/08_direct_light.h"
#include "raylab/trace_recorder.h"

#include <algorithm>
#include <cmath>

namespace raylab {
namespace {

// Turns a point sampled by area into a sample of direction from `reference_point`.
std::optional<LightSample> area_sample(const ShapeSample& shape, const glm::vec3& radiance,
                                       const glm::vec3& reference_point) {
  std::optional<LightSample> result;  // every return hands it back: see SceneGeometry::intersect
  const glm::vec3 to_light = shape.point - reference_point;
  const float distance_squared = glm::dot(to_light, to_light);
  if (!(distance_squared > 0.0f) || !(shape.pdf_area > 0.0f)) return result;
  const float distance = std::sqrt(distance_squared);
  const glm::vec3 direction = to_light / distance;
  const float cos_light = -glm::dot(shape.normal, direction);
  if (!(cos_light > 0.0f)) return result;  // seen edge-on (no solid angle) or from the back (dark)
  const float pdf = area_pdf_to_solid_angle(shape.pdf_area, distance, cos_light);  // stage 08
  if (!std::isfinite(pdf)) return result;
  LightSample& sample = result.emplace();
  sample.radiance = radiance;
  sample.direction = direction;
  sample.distance = distance;
  sample.pdf = pdf;
  sample.point = shape.point;
  return result;
}

// The solid-angle density of reaching a point at distance t along unit `direction` on a
// surface of normal `normal` sampled with density pdf_area.
double solid_angle_density(double pdf_area, double t, const glm::dvec3& direction, const glm::dvec3& normal) {
  const double cos_light = std::fabs(glm::dot(direction, normal));
  return cos_light > 0.0 ? pdf_area * t * t / cos_light : 0.0;
}

// sample_li while a trace records (raylab/trace_recorder.h).
RAYLAB_RECORDED_VERSION std::optional<LightSample> sample_li_recorded(const Light& light,
                                                                      const glm::vec3& reference_point, glm::vec2 u) {
  PausedRecording paused;
  return record_light_sample(*paused.recorder, light, reference_point, u, sample_li(light, reference_point, u));
}

}  // namespace

std::optional<LightSample> sample_li(const Light& light, const glm::vec3& reference_point, glm::vec2 u) {
  if (RAYLAB_UNLIKELY(active_trace_recorder)) return sample_li_recorded(light, reference_point, u);
  switch (light.kind) {
    case LightKind::Point: {
      const glm::vec3 to_light = light.position - reference_point;
      const float distance_squared = glm::dot(to_light, to_light);
      if (!(distance_squared > 0.0f)) return std::nullopt;
      LightSample sample;
      sample.distance = std::sqrt(distance_squared);
      sample.direction = to_light / sample.distance;
      sample.radiance = light.intensity / distance_squared;  // inverse-square falloff
      sample.pdf = 1.0f;
      sample.is_delta = true;
      sample.point = light.position;
      return sample;
    }
    case LightKind::Triangle:
      return area_sample(sample_triangle(light.p0, light.p1, light.p2, light.normal, u), light.radiance,
                         reference_point);
    case LightKind::Sphere:
      return area_sample(sample_sphere(light.sphere, u), light.radiance, reference_point);
  }
  return std::nullopt;
}

float pdf_li(const Light& light, const glm::vec3& reference_point, const glm::vec3& direction) {
  // In double, from the plane or the quadratic directly: the density is exact for any
  // direction, also where a float intersection test would be unsure.
  const glm::dvec3 origin(reference_point), d(direction);
  switch (light.kind) {
    case LightKind::Point: return 0.0f;  // a delta light: no density over directions
    case LightKind::Triangle: {
      const glm::dvec3 p0(light.p0), p1(light.p1), p2(light.p2);
      const glm::dvec3 normal_unnormalised = glm::cross(p1 - p0, p2 - p0);
      const double twice_area = glm::length(normal_unnormalised);
      if (!(twice_area > 0.0)) return 0.0f;
      const glm::dvec3 normal = normal_unnormalised / twice_area;
      const double denominator = glm::dot(d, normal);
      if (denominator == 0.0) return 0.0f;
      const double t = glm::dot(p0 - origin, normal) / denominator;
      if (!(t > 0.0)) return 0.0f;
      const glm::dvec3 point = origin + t * d;
      // Inside: the three sub-triangles towards the point all have the winding of the whole.
      const double b0 = glm::dot(glm::cross(p2 - p1, point - p1), normal);
      const double b1 = glm::dot(glm::cross(p0 - p2, point - p2), normal);
      const double b2 = glm::dot(glm::cross(p1 - p0, point - p0), normal);
      if (b0 < 0.0 || b1 < 0.0 || b2 < 0.0) return 0.0f;
      return static_cast<float>(solid_angle_density(2.0 / twice_area, t, d, normal));
    }
    case LightKind::Sphere: {
      // Uniform area sampling can reach a direction at both of the line's points on the
      // sphere: the densities add.
      const glm::dvec3 center(light.sphere.center);
      const double radius = light.sphere.radius;
      const glm::dvec3 offset = origin - center;
      const double a = glm::dot(d, d), half_b = glm::dot(offset, d), c = glm::dot(offset, offset) - radius * radius;
      const double discriminant = half_b * half_b - a * c;
      if (!(discriminant > 0.0)) return 0.0f;
      const double root = std::sqrt(discriminant);
      const double pdf_area = 1.0 / (4.0 * 3.14159265358979323846 * radius * radius);
      double density = 0.0;
      for (const double t : {(-half_b - root) / a, (-half_b + root) / a})
        if (t > 0.0) density += solid_angle_density(pdf_area, t, d, (origin + t * d - center) / radius);
      return static_cast<float>(density);
    }
  }
  return 0.0f;
}

glm::vec3 light_power(const Light& light) {
  switch (light.kind) {
    case LightKind::Point: return 4.0f * kPi * light.intensity;
    case LightKind::Triangle:
    case LightKind::Sphere: return kPi * light.area * light.radiance;
  }
  return glm::vec3(0.0f);
}

LightSet::LightSet(const Scene& scene) {
  for (const PointLight& point : scene.lights) {
    Light light;
    light.kind = LightKind::Point;
    light.position = point.position;
    light.intensity = point.intensity;
    lights_.push_back(light);
  }
  auto emits = [&](std::uint32_t material) {
    return material < scene.materials.size() && scene.materials[material].emission != glm::vec3(0.0f);
  };
  for (const Sphere& sphere : scene.spheres) {
    if (!emits(sphere.material)) continue;
    Light light;
    light.kind = LightKind::Sphere;
    light.sphere = sphere;
    light.radiance = scene.materials[sphere.material].emission;
    light.area = sphere_area(sphere);
    lights_.push_back(light);
  }
  for (const TriangleMesh& mesh : scene.meshes) {
    if (!emits(mesh.material)) continue;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      Light light;
      light.kind = LightKind::Triangle;
      light.p0 = mesh.positions[mesh.indices[3 * t]];
      light.p1 = mesh.positions[mesh.indices[3 * t + 1]];
      light.p2 = mesh.positions[mesh.indices[3 * t + 2]];
      light.area = triangle_area(light.p0, light.p1, light.p2);
      if (!(light.area > 0.0f)) continue;  // a degenerate triangle emits nothing
      light.normal = triangle_normal(light.p0, light.p1, light.p2);
      light.radiance = scene.materials[mesh.material].emission;
      lights_.push_back(light);
    }
  }
}

std::size_t LightSet::choose(float u, float* probability) const {
  const std::size_t count = lights_.size();
  if (probability) *probability = 1.0f / static_cast<float>(count);
  const std::size_t index = std::min(count - 1, static_cast<std::size_t>(u * static_cast<float>(count)));
  if (RAYLAB_UNLIKELY(active_trace_recorder))
    return record_light_choice(*active_trace_recorder, u, index, 1.0f / static_cast<float>(count));
  return index;
}

float LightSet::pdf_li(const glm::vec3& reference_point, const glm::vec3& direction) const {
  if (lights_.empty()) return 0.0f;
  float sum = 0.0f;
  for (const Light& light : lights_) sum += raylab::pdf_li(light, reference_point, direction);
  return sum / static_cast<float>(lights_.size());  // each light is chosen with probability 1 / size()
}

}  // namespace raylab
