#include "raylab/shapes.h"

#include "raylab/sampling.h"

namespace raylab {

float triangle_area(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  return 0.5f * glm::length(glm::cross(p1 - p0, p2 - p0));
}

ShapeSample sample_triangle(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, glm::vec2 u) {
  const glm::vec2 b = sample_uniform_triangle(u);
  ShapeSample sample;
  sample.point = (1.0f - b.x - b.y) * p0 + b.x * p1 + b.y * p2;
  const glm::vec3 cross = glm::cross(p1 - p0, p2 - p0);
  const float twice_area = glm::length(cross);
  if (twice_area > 0.0f) {
    sample.normal = cross / twice_area;
    sample.pdf_area = 2.0f / twice_area;
  }
  return sample;
}

ShapeSample sample_sphere(const Sphere& sphere, glm::vec2 u) {
  ShapeSample sample;
  sample.normal = sample_uniform_sphere(u);
  sample.point = sphere.center + sphere.radius * sample.normal;
  sample.pdf_area = 1.0f / sphere_area(sphere);
  return sample;
}

}  // namespace raylab
