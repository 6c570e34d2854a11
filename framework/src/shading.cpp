// Whitted-style shading, following GAMES101 assignment 5 (Renderer.cpp, castRay) so that the
// picture matches the course's, with robust secondary-ray origins instead of an epsilon.
#include "raylab/shading.h"

#include <algorithm>
#include <cmath>

namespace raylab {

glm::vec3 reflect(const glm::vec3& incident, const glm::vec3& normal) {
  return incident - 2.0f * glm::dot(incident, normal) * normal;
}

glm::vec3 refract(const glm::vec3& incident, const glm::vec3& normal, float ior) {
  float cos_incident = std::clamp(glm::dot(incident, normal), -1.0f, 1.0f);
  float eta_incident = 1.0f, eta_transmitted = ior;
  glm::vec3 n = normal;
  if (cos_incident < 0.0f) {
    cos_incident = -cos_incident;  // entering: the normal faces the incoming ray
  } else {
    std::swap(eta_incident, eta_transmitted);  // leaving the object
    n = -normal;
  }
  const float eta = eta_incident / eta_transmitted;
  const float k = 1.0f - eta * eta * (1.0f - cos_incident * cos_incident);
  if (k < 0.0f) return glm::vec3(0.0f);  // total internal reflection
  return eta * incident + (eta * cos_incident - std::sqrt(k)) * n;
}

float fresnel_reflectance(const glm::vec3& incident, const glm::vec3& normal, float ior) {
  float cos_incident = std::clamp(glm::dot(incident, normal), -1.0f, 1.0f);
  float eta_incident = 1.0f, eta_transmitted = ior;
  if (cos_incident > 0.0f) std::swap(eta_incident, eta_transmitted);
  const float sin_transmitted =
      eta_incident / eta_transmitted * std::sqrt(std::max(0.0f, 1.0f - cos_incident * cos_incident));
  if (sin_transmitted >= 1.0f) return 1.0f;  // total internal reflection
  const float cos_transmitted = std::sqrt(std::max(0.0f, 1.0f - sin_transmitted * sin_transmitted));
  cos_incident = std::fabs(cos_incident);
  const float r_s = (eta_transmitted * cos_incident - eta_incident * cos_transmitted) /
                    (eta_transmitted * cos_incident + eta_incident * cos_transmitted);
  const float r_p = (eta_incident * cos_incident - eta_transmitted * cos_transmitted) /
                    (eta_incident * cos_incident + eta_transmitted * cos_transmitted);
  return 0.5f * (r_s * r_s + r_p * r_p);
}

glm::vec3 offset_ray_origin(const SurfaceHit& hit, const glm::vec3& direction) {
  const glm::vec3& n = hit.geometric_normal;
  const float distance = glm::dot(glm::abs(n), hit.point_error);
  glm::vec3 offset = distance * n;
  if (glm::dot(direction, n) < 0.0f) offset = -offset;
  glm::vec3 origin = hit.point + offset;
  // Round away from the surface so that the offset survives the addition's rounding.
  for (int axis = 0; axis < 3; ++axis) {
    if (offset[axis] > 0.0f) origin[axis] = std::nextafter(origin[axis], kInfinity);
    else if (offset[axis] < 0.0f) origin[axis] = std::nextafter(origin[axis], -kInfinity);
  }
  return origin;
}

ShadingStats& ShadingStats::operator+=(const ShadingStats& other) {
  camera_rays += other.camera_rays;
  reflection_rays += other.reflection_rays;
  refraction_rays += other.refraction_rays;
  shadow_rays += other.shadow_rays;
  rays_outside_bounds += other.rays_outside_bounds;
  return *this;
}

Integrator::Integrator(const Scene& scene_, const SceneGeometry& geometry_, int max_depth_, const Skips& skips_)
    : scene(scene_), geometry(geometry_), needs(analyse_scene(scene_)), max_depth(max_depth_), skips(skips_) {}

namespace {

glm::vec3 diffuse_color_at(const Material& material, const SurfaceHit& hit) {
  if (!material.checkerboard || !hit.has_texcoord) return material.diffuse_color;
  const Checkerboard& board = *material.checkerboard;
  auto fraction = [](float x) { return x - std::floor(x); };  // in [0, 1), also below zero
  const bool s_half = fraction(hit.texcoord.x * board.scale) > 0.5f;
  const bool t_half = fraction(hit.texcoord.y * board.scale) > 0.5f;
  return (s_half != t_half) ? board.color_b : board.color_a;
}

Ray spawn_ray(const SurfaceHit& hit, const glm::vec3& direction) {
  Ray ray;
  ray.origin = offset_ray_origin(hit, direction);
  ray.direction = direction;
  return ray;
}

}  // namespace

namespace {

enum class RayKind { Camera, Reflection, Refraction };

// The colour arriving along `ray`, which is `depth` bounces from the camera.
glm::vec3 trace(const Integrator& integrator, const Ray& ray, int depth, RayKind kind, ShadingStats& stats) {
  const Scene& scene = integrator.scene;
  const Skips& skips = integrator.skips;
  switch (kind) {
    case RayKind::Camera: ++stats.camera_rays; break;
    case RayKind::Reflection: ++stats.reflection_rays; break;
    case RayKind::Refraction: ++stats.refraction_rays; break;
  }
  if (skips.rays_outside_bounds && !may_hit_scene(integrator.needs, ray)) {
    ++stats.rays_outside_bounds;
    return scene.background;
  }
  const std::optional<SurfaceHit> hit = integrator.geometry.intersect(ray);
  if (!hit) return scene.background;

  const Material& material = scene.materials[hit->material];
  const glm::vec3 direction = glm::normalize(ray.direction);
  const glm::vec3& normal = hit->geometric_normal;
  // A bounce is traced only when it can contribute: within max_depth, and (when skipping) with
  // a weight above zero.
  const bool may_bounce = depth < integrator.max_depth;
  auto bounce = [&](float weight, const glm::vec3& bounce_direction, RayKind bounce_kind) {
    if (!may_bounce || (skips.zero_weight_bounces && weight == 0.0f)) return glm::vec3(0.0f);
    return weight * trace(integrator, spawn_ray(*hit, bounce_direction), depth + 1, bounce_kind, stats);
  };

  switch (material.kind) {
    case MaterialKind::ReflectiveRefractive: {
      const float reflectance = fresnel_reflectance(direction, normal, material.index_of_refraction);
      glm::vec3 color = bounce(reflectance, glm::normalize(reflect(direction, normal)), RayKind::Reflection);
      if (reflectance < 1.0f)  // no refracted ray under total internal reflection
        color += bounce(1.0f - reflectance, glm::normalize(refract(direction, normal, material.index_of_refraction)),
                        RayKind::Refraction);
      return color;
    }
    case MaterialKind::Reflective: {
      const float reflectance = fresnel_reflectance(direction, normal, material.index_of_refraction);
      return bounce(reflectance, reflect(direction, normal), RayKind::Reflection);
    }
    case MaterialKind::DiffuseGlossy:
    default: {
      // Surfaces are two-sided: shade with the normal that faces the viewer.
      const glm::vec3 facing_normal = glm::dot(direction, normal) < 0.0f ? normal : -normal;
      const glm::vec3 diffuse_color = diffuse_color_at(material, *hit);
      const bool diffuse_visible = material.kd != 0.0f && diffuse_color != glm::vec3(0.0f);
      glm::vec3 light_amount(0.0f), specular(0.0f);
      for (const PointLight& light : scene.lights) {
        const glm::vec3 light_direction = glm::normalize(light.position - hit->point);
        const float cos_light = glm::dot(light_direction, facing_normal);
        // A light behind the surface, or a surface with no diffuse colour, needs no shadow ray.
        const bool needs_shadow_ray = !skips.needless_shadow_rays || (cos_light > 0.0f && diffuse_visible);
        if (needs_shadow_ray) {
          // Towards the light, stopping just short of it.
          Ray shadow;
          shadow.origin = offset_ray_origin(*hit, light_direction);
          shadow.direction = light.position - shadow.origin;
          shadow.t_max = 1.0f - 1e-4f;
          ++stats.shadow_rays;
          // Any hit ends a shadow ray; without that skip, the closest hit is searched instead.
          const bool blocked = skips.any_hit_shadow_rays ? integrator.geometry.occluded(shadow)
                                                         : integrator.geometry.intersect(shadow).has_value();
          if (!blocked && cos_light > 0.0f) light_amount += light.intensity * cos_light;
        }
        const glm::vec3 light_reflected = reflect(-light_direction, facing_normal);
        specular += std::pow(std::max(0.0f, -glm::dot(light_reflected, direction)), material.specular_exponent) *
                    light.intensity;
      }
      return light_amount * diffuse_color * material.kd + specular * material.ks;
    }
  }
}

}  // namespace

glm::vec3 trace_camera_ray(const Integrator& integrator, const Ray& ray, ShadingStats& stats) {
  return trace(integrator, ray, 0, RayKind::Camera, stats);
}

}  // namespace raylab
