// The kit's own camera rays, sphere and triangle tests, in double (the sphere's roots in long
// double, oracles.h), with the conventions of stages 01-03 (their headers). The autograder traces
// the later stages' scenes with them, so that a mistake in stages 01-05 costs points in its own
// stage only; `raylab trace` holds each of your calls against them.
#pragma once

#include "raylab/camera.h"
#include "raylab/geometry.h"
#include "raylab/ray.h"
#include "raylab/stages/03_triangle.h"

#include <glm/glm.hpp>

#include <optional>

namespace raylab::testkit {

// Stage 01's mapping: raster (x + s.x, y + s.y) to NDC in [0, 1], to screen [-1, 1] scaled by
// tan(fov / 2) (and the aspect ratio on x), y up; a unit direction in the camera's frame.
Ray exact_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel);
// The nearer root of |o + t d - c|^2 = r^2 in the ray's interval (the farther one from inside),
// each root rounded to float before the interval test, as the float the renderer receives.
std::optional<float> exact_sphere_test(const Ray& ray, const glm::vec3& center, float radius);
// Cramer's rule in double: the hit, from either side, with t in the ray's open interval.
std::optional<TriangleHit> exact_triangle_test(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                               const glm::vec3& p2);

// The three as the functions a SceneGeometry traces with.
TracingFunctions exact_tracing();

}  // namespace raylab::testkit
