#include "raylab/shapes.h"

#include "raylab/stages/07_sampling.h"

namespace raylab {

float triangle_area(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  return 0.5f * glm::length(glm::cross(p1 - p0, p2 - p0));
}

glm::vec3 triangle_normal(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  const glm::vec3 cross = glm::cross(p1 - p0, p2 - p0);
  const float twice_area = glm::length(cross);
  return twice_area > 0.0f ? cross / twice_area : glm::vec3(0.0f);
}

ShapeSample sample_triangle(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, glm::vec2 u) {
  return sample_triangle(p0, p1, p2, triangle_normal(p0, p1, p2), u);
}

ShapeSample sample_triangle(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& normal,
                            glm::vec2 u) {
  const Barycentrics b = sample_uniform_triangle(u);
  ShapeSample sample;
  sample.point = (1.0f - b.barycentric_b1 - b.barycentric_b2) * p0 + b.barycentric_b1 * p1 + b.barycentric_b2 * p2;
  if (normal != glm::vec3(0.0f)) {
    sample.normal = normal;
    sample.pdf_area = uniform_triangle_pdf(p0, p1, p2);
  }
  return sample;
}

ShapeSample sample_sphere(const Sphere& sphere, glm::vec2 u) {
  ShapeSample sample;
  const glm::vec3 outward = sample_uniform_sphere(u);
  sample.point = sphere.center + sphere.radius * outward;
  sample.normal = sphere.faces_inward ? -outward : outward;
  // Directions per steradian of the unit sphere are points per unit area of this one over r^2.
  sample.pdf_area = uniform_sphere_pdf(outward) / (sphere.radius * sphere.radius);
  return sample;
}

}  // namespace raylab
