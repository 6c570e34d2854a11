// What area lights need of a shape: its surface area, and a point on it chosen uniformly by
// area (density 1 / area) with the surface normal there.
#pragma once

#include "raylab/math.h"
#include "raylab/scene.h"

namespace raylab {

struct ShapeSample {
  glm::vec3 point{0.0f};
  glm::vec3 normal{0.0f};  // unit; by winding for triangles, the sphere's facing (Sphere::faces_inward)
  float pdf_area = 0.0f;   // density per unit area: 1 / area
};

float triangle_area(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2);
// Its unit normal, cross(p1 - p0, p2 - p0) normalised; zero for a degenerate triangle.
glm::vec3 triangle_normal(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2);
// u in [0, 1)^2. A degenerate triangle (area 0) gives pdf_area = 0.
ShapeSample sample_triangle(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, glm::vec2 u);
// The same, with the triangle's triangle_normal computed once by the caller (a light's, at
// every sample).
ShapeSample sample_triangle(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& normal,
                            glm::vec2 u);

inline float sphere_area(const Sphere& sphere) { return 4.0f * kPi * sphere.radius * sphere.radius; }
ShapeSample sample_sphere(const Sphere& sphere, glm::vec2 u);

}  // namespace raylab
