// What a scene can use, decided once before rendering, so that the renderer leaves out the
// rest: no shadow rays without lights (or without a surface they could light), no reflection
// or refraction rays without materials that make them, and camera rays that miss the
// scene's bounding sphere end at once.
#pragma once

#include "raylab/ray.h"
#include "raylab/scene.h"

namespace raylab {

struct SceneNeeds {
  bool shadow_rays = false;      // point lights and a diffuse_glossy material to light
  bool reflection_rays = false;  // a reflective or glass material
  bool refraction_rays = false;  // a glass material
  bool has_geometry = false;
  // A sphere around every object (in double: the test must never reject a real hit).
  glm::dvec3 bounds_center{0.0};
  double bounds_radius = 0.0;
};

SceneNeeds analyse_scene(const Scene& scene);

// False only when the ray cannot hit anything: it misses the scene's bounding sphere.
bool may_hit_scene(const SceneNeeds& needs, const Ray& ray);

}  // namespace raylab
