// Stage 02_sphere: where a ray first meets a sphere.
// Write it in assignments/02_sphere/sphere.cpp; handout: docs/02_sphere.md.
#pragma once

#include "raylab/ray.h"

#include <optional>

namespace raylab {

// The smallest t in the open interval (ray.t_min, ray.t_max) at which the ray meets the
// sphere's surface, or std::nullopt if there is none.
std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center,
                                          float sphere_radius);

}  // namespace raylab
