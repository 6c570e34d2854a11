// Exact answers for the float inputs of a kernel, in long double: what the autograder's
// robustness cases are checked in with and what the stress suite measures errors against.
// One oracle per kernel, so that the two can never disagree.
#pragma once

#include "raylab/ray.h"

#include <glm/glm.hpp>

#include <optional>

namespace raylab::testkit {

// Both roots t0 <= t1 of |origin + t direction - center|^2 = radius^2 for the float inputs,
// computed in long double without cancellation: the discriminant from the distance between
// the centre and the ray's line, the roots as q / a and c / q. For a double root (a ray
// tangent to the sphere) t0 == t1, also when it is at t = 0, where c / q would be 0 / 0.
struct SphereRoots {
  long double t0 = 0, t1 = 0;
};
// nullopt when the ray's line misses the sphere or the direction is zero. `margin` (out, if
// given) is |discriminant| relative to its scale (radius^2): near 0 the decision hit/miss is
// ill-conditioned and a float kernel may go either way.
std::optional<SphereRoots> exact_sphere_roots(const Ray& ray, const glm::vec3& center, float radius,
                                              long double* margin = nullptr);

// The smallest root in (t_min, t_max), or nullopt: the stage 02 contract, exactly.
std::optional<long double> exact_sphere_hit(const Ray& ray, const glm::vec3& center, float radius,
                                            long double* margin = nullptr);

}  // namespace raylab::testkit
