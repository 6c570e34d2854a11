// Stage 07_sampling: warps from uniform random numbers to points and directions, each with its
// density (pdf). Write them in assignments/07_sampling/sampling.cpp (its comments are the full
// contract); handout: docs/07_sampling.md. The framework's BSDFs and lights sample with these.
//
// Conventions: `uniform_random` is a pair of independent numbers, each uniform in [0, 1).
// Directions are unit vectors in a LOCAL frame whose z axis is the surface normal (the caller
// turns them into world space with raylab::Frame, raylab/sampling.h), so z = cos(theta), and
// "below the surface" means z < 0. Densities of directions are per unit solid angle
// (steradian); densities of points per unit area.
#pragma once

#include <glm/glm.hpp>

#include <ostream>

namespace raylab {

// A point of a triangle (p0, p1, p2) by its barycentric coordinates:
//   point = (1 - barycentric_b1 - barycentric_b2) * p0 + barycentric_b1 * p1 + barycentric_b2 * p2
// (the same weights as stage 03's TriangleHit).
struct Barycentrics {
  float barycentric_b1 = 0.0f;  // weight of p1
  float barycentric_b2 = 0.0f;  // weight of p2
};
std::ostream& operator<<(std::ostream& out, const Barycentrics& barycentrics);

// A direction of the hemisphere z >= 0, every direction equally likely; its density 1 / (2 pi)
// for z >= 0 and 0 below the surface.
glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random);
float uniform_hemisphere_pdf(const glm::vec3& direction);

// A direction of the hemisphere z >= 0 with density cos(theta) / pi = z / pi (0 below the
// surface): what a diffuse (Lambertian) surface reflects with.
glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random);
float cosine_hemisphere_pdf(const glm::vec3& direction);

// A direction of the whole unit sphere, every direction equally likely: density 1 / (4 pi).
glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random);
float uniform_sphere_pdf(const glm::vec3& direction);

// A point of the unit disk (radius 1, centre 0), uniform by area: density 1 / pi inside the
// disk (edge included), 0 outside.
glm::vec2 sample_uniform_disk(glm::vec2 uniform_random);
float uniform_disk_pdf(glm::vec2 point);

// A point of a triangle, uniform by area, as barycentrics (valid for every triangle: the
// caller combines them with the corners); the density of such points on the triangle
// (p0, p1, p2) is 1 / area (per unit area, the same everywhere on it).
Barycentrics sample_uniform_triangle(glm::vec2 uniform_random);
float uniform_triangle_pdf(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2);

}  // namespace raylab
