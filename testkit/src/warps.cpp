#include "raylab/testkit/warps.h"

#include <algorithm>
#include <cmath>

namespace raylab::testkit {
namespace {

constexpr double kPi = 3.14159265358979323846;

double angle_of(double x, double y) {
  const double phi = std::atan2(y, x);
  return phi < 0.0 ? phi + 2.0 * kPi : phi;
}

double at_most_one(double value) { return value >= 1.0 && value <= 1.0 + 1e-5 ? std::nextafter(1.0, 0.0) : value; }

}  // namespace

const char* warp_sample_function(Warp warp) {
  switch (warp) {
    case Warp::UniformHemisphere: return "sample_uniform_hemisphere";
    case Warp::CosineHemisphere: return "sample_cosine_hemisphere";
    case Warp::UniformSphere: return "sample_uniform_sphere";
    case Warp::UniformDisk: return "sample_uniform_disk";
    case Warp::UniformTriangle: return "sample_uniform_triangle";
  }
  return "a warp";
}

const char* warp_pdf_function(Warp warp) {
  switch (warp) {
    case Warp::UniformHemisphere: return "uniform_hemisphere_pdf";
    case Warp::CosineHemisphere: return "cosine_hemisphere_pdf";
    case Warp::UniformSphere: return "uniform_sphere_pdf";
    case Warp::UniformDisk: return "uniform_disk_pdf";
    case Warp::UniformTriangle: return "uniform_triangle_pdf";
  }
  return "a density";
}

WarpGrid warp_grid(Warp warp) {
  // Rows split z at 0 (the hemisphere's rim), columns and rows of the disk and triangle end at
  // its edge: every jump of an intended density lies on a cell border.
  if (is_direction_warp(warp)) return {40, 20, 0.0, 2.0 * kPi, -1.0, 1.0};
  if (warp == Warp::UniformDisk) return {40, 20, 0.0, 2.0 * kPi, 0.0, 1.0};
  return {20, 20, 0.0, 1.0, 0.0, 1.0};
}

glm::dvec2 warp_parameters(Warp warp, const glm::vec3& sample) {
  const glm::dvec3 s(sample);
  if (is_direction_warp(warp)) {
    const double length = glm::length(s);
    return {angle_of(s.x, s.y), std::clamp(s.z / length, -1.0, std::nextafter(1.0, 0.0))};
  }
  if (warp == Warp::UniformDisk) return {angle_of(s.x, s.y), at_most_one(std::sqrt(s.x * s.x + s.y * s.y))};
  const double sum = s.x + s.y;
  return {sum > 0.0 ? at_most_one(s.y / sum) : 0.0, at_most_one(sum)};
}

glm::vec3 warp_pdf_argument(Warp warp, double u, double v) {
  if (is_direction_warp(warp)) {
    const double radius = std::sqrt(std::max(0.0, 1.0 - v * v));
    return glm::vec3(glm::dvec3(radius * std::cos(u), radius * std::sin(u), v));
  }
  if (warp == Warp::UniformDisk) return glm::vec3(glm::dvec3(v * std::cos(u), v * std::sin(u), 0.0));
  return glm::vec3(glm::dvec3(v * (1.0 - u), v * u, 0.0));  // barycentrics (b1, b2)
}

double warp_jacobian(Warp warp, double, double v) { return is_direction_warp(warp) ? 1.0 : v; }

double intended_pdf(Warp warp, double, double v) {
  switch (warp) {
    case Warp::UniformHemisphere: return v >= 0.0 ? 1.0 / (2.0 * kPi) : 0.0;
    case Warp::CosineHemisphere: return v >= 0.0 ? v / kPi : 0.0;
    case Warp::UniformSphere: return 1.0 / (4.0 * kPi);
    case Warp::UniformDisk: return 1.0 / kPi;
    case Warp::UniformTriangle: return 2.0;
  }
  return 0.0;
}

}  // namespace raylab::testkit
