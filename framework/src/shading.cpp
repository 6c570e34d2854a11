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

glm::vec3 trace_whitted(const Scene& scene, const SceneGeometry& geometry, const Ray& ray,
                        int depth, int max_depth, ShadingStats& stats) {
  if (depth > max_depth) return glm::vec3(0.0f);
  ++stats.rays;
  const std::optional<SurfaceHit> hit = geometry.intersect(ray);
  if (!hit) return scene.background;

  const Material& material = scene.materials[hit->material];
  const glm::vec3 direction = glm::normalize(ray.direction);
  const glm::vec3& normal = hit->geometric_normal;

  switch (material.kind) {
    case MaterialKind::ReflectiveRefractive: {
      const float reflectance = fresnel_reflectance(direction, normal, material.index_of_refraction);
      const glm::vec3 reflected = glm::normalize(reflect(direction, normal));
      glm::vec3 color = reflectance *
          trace_whitted(scene, geometry, spawn_ray(*hit, reflected), depth + 1, max_depth, stats);
      if (reflectance < 1.0f) {  // no refracted ray under total internal reflection
        const glm::vec3 refracted = glm::normalize(refract(direction, normal, material.index_of_refraction));
        color += (1.0f - reflectance) *
            trace_whitted(scene, geometry, spawn_ray(*hit, refracted), depth + 1, max_depth, stats);
      }
      return color;
    }
    case MaterialKind::Reflective: {
      const float reflectance = fresnel_reflectance(direction, normal, material.index_of_refraction);
      const glm::vec3 reflected = reflect(direction, normal);
      return reflectance *
             trace_whitted(scene, geometry, spawn_ray(*hit, reflected), depth + 1, max_depth, stats);
    }
    case MaterialKind::DiffuseGlossy:
    default: {
      // Surfaces are two-sided: shade with the normal that faces the viewer.
      const glm::vec3 facing_normal = glm::dot(direction, normal) < 0.0f ? normal : -normal;
      glm::vec3 light_amount(0.0f), specular(0.0f);
      for (const PointLight& light : scene.lights) {
        const glm::vec3 to_light = light.position - hit->point;
        const glm::vec3 light_direction = glm::normalize(to_light);
        const float cos_light = glm::dot(light_direction, facing_normal);
        if (cos_light > 0.0f) {
          // Shadow ray towards the light, stopping just short of it, any hit ends it.
          Ray shadow;
          shadow.origin = offset_ray_origin(*hit, light_direction);
          shadow.direction = light.position - shadow.origin;
          shadow.t_max = 1.0f - 1e-4f;
          ++stats.rays;
          if (!geometry.occluded(shadow)) light_amount += light.intensity * cos_light;
        }
        const glm::vec3 light_reflected = reflect(-light_direction, facing_normal);
        specular += std::pow(std::max(0.0f, -glm::dot(light_reflected, direction)),
                             material.specular_exponent) * light.intensity;
      }
      return light_amount * diffuse_color_at(material, *hit) * material.kd + specular * material.ks;
    }
  }
}

}  // namespace raylab
