// What a scene can use, decided once before rendering. Some skips need no analysis: without
// lights no shadow ray is made, without glass no refraction ray (shading.cpp). What does: the
// scene's bounding sphere, so that rays that miss it end at once.
#pragma once

#include "raylab/ray.h"
#include "raylab/scene.h"

namespace raylab {

struct SceneNeeds {
  bool has_geometry = false;
  // A sphere around every object (in double: the test must never reject a real hit).
  glm::dvec3 bounds_center{0.0};
  double bounds_radius = 0.0;
};

SceneNeeds analyse_scene(const Scene& scene);

// False only when the ray cannot hit anything: it misses the scene's bounding sphere.
bool may_hit_scene(const SceneNeeds& needs, const Ray& ray);

}  // namespace raylab
