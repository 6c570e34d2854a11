// The grader's own stage 07 (the warps of raylab/stages/07_sampling.h, in double precision): the
// stage servers that grade stages 08, 09 and 09b link these instead of yours (stages.json:
// "grader_versions"), so that a mistake in your stage 07 costs points at stage 07 only. Each warp
// maps the same random numbers to the same point as the reference, up to rounding.
#include "raylab/stages/07_sampling.h"

#include <algorithm>
#include <cmath>

namespace raylab {
namespace {

constexpr double kPiInDouble = 3.14159265358979323846;

// A point of the unit sphere at height z and azimuth 2 pi u.
glm::vec3 at_height(double z, double u) {
  const double ring = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPiInDouble * u;
  return glm::vec3(glm::dvec3(ring * std::cos(phi), ring * std::sin(phi), z));
}

}  // namespace

glm::vec3 sample_uniform_hemisphere(glm::vec2 u) { return at_height(1.0 - double(u.x), u.y); }

float uniform_hemisphere_pdf(const glm::vec3& direction) {
  return direction.z >= 0.0f ? float(1.0 / (2.0 * kPiInDouble)) : 0.0f;
}

// Shirley and Chiu's concentric map onto the disk, lifted onto the hemisphere (Malley's method).
glm::vec3 sample_cosine_hemisphere(glm::vec2 u) {
  const glm::dvec2 disk(sample_uniform_disk(u));
  return glm::vec3(glm::dvec3(disk, std::sqrt(std::max(0.0, 1.0 - glm::dot(disk, disk)))));
}

float cosine_hemisphere_pdf(const glm::vec3& direction) {
  return direction.z > 0.0f ? float(double(direction.z) / kPiInDouble) : 0.0f;
}

glm::vec3 sample_uniform_sphere(glm::vec2 u) { return at_height(1.0 - 2.0 * double(u.x), u.y); }

float uniform_sphere_pdf(const glm::vec3&) { return float(1.0 / (4.0 * kPiInDouble)); }

glm::vec2 sample_uniform_disk(glm::vec2 u) {
  const double a = 2.0 * double(u.x) - 1.0, b = 2.0 * double(u.y) - 1.0;
  if (a == 0.0 && b == 0.0) return glm::vec2(0.0f);
  const bool wide = std::fabs(a) > std::fabs(b);
  const double radius = wide ? a : b;
  const double angle = wide ? (kPiInDouble / 4.0) * (b / a) : kPiInDouble / 2.0 - (kPiInDouble / 4.0) * (a / b);
  return glm::vec2(glm::dvec2(radius * std::cos(angle), radius * std::sin(angle)));
}

float uniform_disk_pdf(glm::vec2 point) {
  return glm::dot(glm::dvec2(point), glm::dvec2(point)) <= 1.0 ? float(1.0 / kPiInDouble) : 0.0f;
}

Barycentrics sample_uniform_triangle(glm::vec2 u) {
  const double root = std::sqrt(double(u.x));
  return Barycentrics{float(root * (1.0 - double(u.y))), float(root * double(u.y))};
}

float uniform_triangle_pdf(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  const double twice_area = glm::length(glm::cross(glm::dvec3(p1) - glm::dvec3(p0), glm::dvec3(p2) - glm::dvec3(p0)));
  return twice_area > 0.0 ? float(2.0 / twice_area) : 0.0f;
}

}  // namespace raylab
