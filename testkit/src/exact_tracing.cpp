#include "raylab/testkit/exact_tracing.h"

#include "raylab/testkit/oracles.h"

#include <cmath>

namespace raylab::testkit {

namespace {

constexpr double kPiInDouble = 3.14159265358979323846;

}  // namespace

// Cramer's rule in double: [-d, e1, e2] (t, b1, b2)^T = o - p0. The hit, from either side, with
// t in the ray's open interval. (A miss on b1 returns before b2 and t are computed: the brute-force
// scenes of stages 08-09b spend most of their time here. b1 > 1 with b2 >= 0 fails b1 + b2 <= 1
// anyway, so the answer is the same.)
std::optional<TriangleHit> exact_triangle_test(const Ray& ray, const glm::vec3& p0_in, const glm::vec3& p1,
                                               const glm::vec3& p2) {
  const glm::dvec3 p0(p0_in), e1 = glm::dvec3(p1) - p0, e2 = glm::dvec3(p2) - p0;
  const glm::dvec3 minus_d = -glm::dvec3(ray.direction), rhs = glm::dvec3(ray.origin) - p0;
  const double det = glm::determinant(glm::dmat3(minus_d, e1, e2));
  if (det == 0.0 || !std::isfinite(det)) return std::nullopt;
  const double b1 = glm::determinant(glm::dmat3(minus_d, rhs, e2)) / det;
  if (!(b1 >= 0 && b1 <= 1)) return std::nullopt;
  const double b2 = glm::determinant(glm::dmat3(minus_d, e1, rhs)) / det;
  if (!(b2 >= 0 && b1 + b2 <= 1)) return std::nullopt;
  const float t = static_cast<float>(glm::determinant(glm::dmat3(rhs, e1, e2)) / det);
  if (!(t > ray.t_min && t < ray.t_max)) return std::nullopt;
  return TriangleHit{t, static_cast<float>(b1), static_cast<float>(b2)};
}

// The testkit's exact roots (stage 02's oracle), each rounded to float before the interval test.
std::optional<float> exact_sphere_test(const Ray& ray, const glm::vec3& center, float radius) {
  const std::optional<testkit::SphereRoots> roots = testkit::exact_sphere_roots(ray, center, radius);
  if (!roots) return std::nullopt;
  for (const long double t : {roots->t0, roots->t1}) {
    const float t_float = static_cast<float>(t);
    if (t_float > ray.t_min && t_float < ray.t_max) return t_float;
  }
  return std::nullopt;
}

Ray exact_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  const double ndc_x = (pixel_x + static_cast<double>(position_in_pixel.x)) / camera.width;
  const double ndc_y = (pixel_y + static_cast<double>(position_in_pixel.y)) / camera.height;
  const double scale = std::tan(static_cast<double>(camera.fov_y_degrees) * (kPiInDouble / 180.0) * 0.5);
  const double aspect = static_cast<double>(camera.width) / camera.height;
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.look_at) - glm::dvec3(camera.position));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
  const glm::dvec3 up = glm::cross(right, forward);
  Ray ray;
  ray.origin = camera.position;
  ray.direction = glm::vec3(glm::normalize((2.0 * ndc_x - 1.0) * aspect * scale * right +
                                           (1.0 - 2.0 * ndc_y) * scale * up + forward));
  return ray;
}

TracingFunctions exact_tracing() {
  TracingFunctions tracing;
  tracing.camera_ray = exact_camera_ray;
  tracing.sphere = exact_sphere_test;
  tracing.triangle = exact_triangle_test;
  return tracing;
}

}  // namespace raylab::testkit
