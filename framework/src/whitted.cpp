// Whitted-style shading, following GAMES101 assignment 5 (Renderer.cpp, castRay) so that the
// picture matches the course's, with robust secondary-ray origins instead of an epsilon.
#include "raylab/integrator.h"

#include <algorithm>
#include <cmath>

namespace raylab {
namespace {

enum class RayKind { Camera, Reflection, Refraction };

// The colour arriving along `ray`, which is `depth` bounces from the camera.
glm::vec3 trace(const RenderContext& context, const Ray& ray, int depth, RayKind kind, ShadingStats& stats) {
  const Scene& scene = context.scene;
  const Skips& skips = context.skips;
  switch (kind) {
    case RayKind::Camera: ++stats.camera_rays; break;
    case RayKind::Reflection: ++stats.reflection_rays; break;
    case RayKind::Refraction: ++stats.refraction_rays; break;
  }
  if (skips.rays_outside_bounds && !may_hit_scene(context.needs, ray)) {
    ++stats.rays_outside_bounds;
    return scene.background;
  }
  const std::optional<SurfaceHit> hit = context.geometry.intersect(ray);
  if (!hit) return scene.background;

  const Material& material = scene.materials[hit->material];
  const glm::vec3 direction = glm::normalize(ray.direction);
  const glm::vec3& normal = hit->geometric_normal;
  // A bounce is traced only when it can contribute: within max_depth, and (when skipping) with
  // a weight above zero.
  const bool may_bounce = depth < context.max_depth;
  auto bounce = [&](float weight, const glm::vec3& bounce_direction, RayKind bounce_kind) {
    if (!may_bounce || (skips.zero_weight_bounces && weight == 0.0f)) return glm::vec3(0.0f);
    return weight * trace(context, spawn_ray(*hit, bounce_direction), depth + 1, bounce_kind, stats);
  };

  // An emitting surface adds its own radiance (seen directly or in a mirror); Whitted
  // shading lights surfaces with the point lights only, not with area lights.
  const bool emits = material.emission != glm::vec3(0.0f);
  auto plus_emission = [&](const glm::vec3& reflected) {
    return emits ? reflected + emitted_radiance(material, *hit, ray.direction) : reflected;
  };
  switch (material.kind) {
    case MaterialKind::ReflectiveRefractive: {
      const float reflectance = fresnel_reflectance(direction, normal, material.index_of_refraction);
      glm::vec3 color = bounce(reflectance, glm::normalize(reflect(direction, normal)), RayKind::Reflection);
      if (reflectance < 1.0f)  // no refracted ray under total internal reflection
        color += bounce(1.0f - reflectance, glm::normalize(refract(direction, normal, material.index_of_refraction)),
                        RayKind::Refraction);
      return plus_emission(color);
    }
    case MaterialKind::Reflective: {
      const float reflectance = fresnel_reflectance(direction, normal, material.index_of_refraction);
      return plus_emission(bounce(reflectance, reflect(direction, normal), RayKind::Reflection));
    }
    case MaterialKind::Mirror:
    case MaterialKind::Microfacet:  // its alpha -> 0 limit: Whitted shading has no rough reflection
      return plus_emission(material.reflectance * bounce(1.0f, reflect(direction, normal), RayKind::Reflection));
    case MaterialKind::DiffuseGlossy:
    case MaterialKind::Diffuse:  // kd 1, ks 0 (scene_schema.cpp)
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
          const bool blocked = skips.any_hit_shadow_rays ? context.geometry.occluded(shadow)
                                                         : context.geometry.intersect(shadow).has_value();
          if (!blocked && cos_light > 0.0f) light_amount += light.intensity * cos_light;
        }
        const glm::vec3 light_reflected = reflect(-light_direction, facing_normal);
        specular += std::pow(std::max(0.0f, -glm::dot(light_reflected, direction)), material.specular_exponent) *
                    light.intensity;
      }
      return plus_emission(light_amount * diffuse_color * material.kd + specular * material.ks);
    }
  }
}

}  // namespace

glm::vec3 whitted_li(const RenderContext& context, const Ray& ray, Sampler& sampler, ShadingStats& stats) {
  (void)sampler;  // Whitted shading is deterministic
  return trace(context, ray, 0, RayKind::Camera, stats);
}

}  // namespace raylab
