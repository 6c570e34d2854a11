// The grader's own geometry (grader_geometry.h): a triangle test shared by the judge's brute-force
// oracle and the stage server's BVH traversal requests, so both see exactly the same hits; and
// the camera rays, sphere and triangle tests that stages 08 and 09 trace their scenes with, so
// that a mistake in stages 01-05 costs points in its own stage only. All in double precision (the
// sphere in long double, from the testkit), with the conventions of stages 01-03 (their headers).
#include "grader_geometry.h"

#include "raylab/testkit/oracles.h"

#include <cmath>

namespace raylab::grading {

namespace {

constexpr double kPiInDouble = 3.14159265358979323846;

// Cramer's rule in double: [-d, e1, e2] (t, b1, b2)^T = o - p0. The hit, from either side, with
// t in the ray's open interval. (A miss on b1 returns before b2 and t are computed: the brute-force
// scenes of stages 08-09b spend most of their time here. b1 > 1 with b2 >= 0 fails b1 + b2 <= 1
// anyway, so the answer is the same.)
std::optional<TriangleHit> triangle_hit_in_double(const Ray& ray, const glm::vec3& p0_in, const glm::vec3& p1,
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

// The nearer root of |o + t d - c|^2 = r^2 in the ray's interval (the farther one from inside):
// the testkit's exact roots (stage 02's oracle), each rounded to float before the interval test,
// as the float the renderer receives.
std::optional<float> sphere_hit_exact(const Ray& ray, const glm::vec3& center, float radius) {
  const std::optional<testkit::SphereRoots> roots = testkit::exact_sphere_roots(ray, center, radius);
  if (!roots) return std::nullopt;
  for (const long double t : {roots->t0, roots->t1}) {
    const float t_float = static_cast<float>(t);
    if (t_float > ray.t_min && t_float < ray.t_max) return t_float;
  }
  return std::nullopt;
}

// Stage 01's mapping: raster (x + s.x, y + s.y) to NDC in [0, 1], to screen [-1, 1] scaled by
// tan(fov / 2) (and the aspect ratio on x), y up; a unit direction in the camera's frame.
Ray camera_ray_in_double(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
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

}  // namespace

std::optional<float> grader_triangle_test(void* triangles, const Ray& ray, std::uint32_t primitive) {
  const protocol::Triangle& triangle = static_cast<const std::vector<protocol::Triangle>*>(triangles)->at(primitive);
  const std::optional<TriangleHit> hit = triangle_hit_in_double(ray, triangle[0], triangle[1], triangle[2]);
  return hit ? std::optional<float>(hit->t_hit) : std::nullopt;
}

std::optional<float> counting_test(void* counted_tests, const Ray& ray, std::uint32_t primitive) {
  auto* counted = static_cast<CountedTests*>(counted_tests);
  ++counted->tests;
  return counted->inner.test(counted->inner.context, ray, primitive);
}

TracingFunctions grader_tracing() {
  TracingFunctions tracing;
  tracing.camera_ray = camera_ray_in_double;
  tracing.sphere = sphere_hit_exact;
  tracing.triangle = triangle_hit_in_double;
  return tracing;
}

}  // namespace raylab::grading
