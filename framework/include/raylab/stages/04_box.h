// Stage 04_box: does a ray pass through an axis-aligned box, and from which t on (slab test)?
// Write it in assignments/04_box/box.cpp (its comment is the full contract);
// handout: docs/04_box.md.
#pragma once

#include "raylab/bounds.h"
#include "raylab/ray.h"

#include <optional>

namespace raylab {

// The entry distance of the ray into the closed box, clipped to the ray's interval:
// max(t_enter, ray.t_min) when the ray's points with t in [ray.t_min, ray.t_max] meet the
// box, else std::nullopt. ray_direction_inverse is (1 / d.x, 1 / d.y, 1 / d.z), computed once
// per ray by the caller (a zero component gives +-infinity, which the test must handle).
std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse,
                                       const Bounds3& box);

// The reciprocal of each component of the ray's direction: 1 / +0 = +infinity and
// 1 / -0 = -infinity, exactly as IEEE 754 says (what the slab test relies on).
inline glm::vec3 ray_direction_inverse_of(const Ray& ray) { return 1.0f / ray.direction; }

}  // namespace raylab
