// 02_sphere: the reference intersect_ray_sphere.
//
// The contract (stages/02_sphere.h): the SMALLEST t with t_min < t < t_max (both ends
// excluded) where origin + t * direction is on the sphere; the direction need not be unit
// length. Every case below is worked by hand; the last one compares with a double solve.
#include "raylab/stages/02_sphere.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>

namespace raylab {
namespace {

constexpr float kTolerance = 1e-5f;


// What came back, printable: "no hit" or "t = ...".
std::string describe(const std::optional<float>& t) {
  return t ? "t = " + std::to_string(*t) : std::string("no hit");
}

// The reference setup: a unit sphere 5 units down -z from the origin. The ray enters at t = 4
// and leaves at t = 6; every number here is exact in float.
const glm::vec3 kCenter(0.0f, 0.0f, -5.0f);
constexpr float kRadius = 1.0f;

TEST(Sphere, HitInFrontReturnsTheNearRoot) {
  const Ray ray = make_ray(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
  const auto t = intersect_ray_sphere(ray, kCenter, kRadius);
  ASSERT_TRUE(t.has_value()) << ray << ", sphere at " << kCenter << " radius " << kRadius;
  EXPECT_NEAR(*t, 4.0f, kTolerance) << ray << ": the near side of the sphere is at z = -4";
}

TEST(Sphere, OffAxisHitMatchesHandSolution) {
  // The ray x = 0.6 crosses the unit sphere where z = -5 +- 0.8: t = 4.2 and 5.8.
  const Ray ray = make_ray(glm::vec3(0.6f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
  const auto t = intersect_ray_sphere(ray, kCenter, kRadius);
  ASSERT_TRUE(t.has_value()) << ray;
  EXPECT_NEAR(*t, 4.2f, kTolerance) << ray;
}

TEST(Sphere, MissReturnsNoHit) {
  // Passes 2 units from the centre of a unit sphere (discriminant < 0).
  const Ray ray = make_ray(glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
  const auto t = intersect_ray_sphere(ray, kCenter, kRadius);
  EXPECT_FALSE(t.has_value()) << ray << ": expected no hit, got " << describe(t);
}

TEST(Sphere, TangentRayTouchesOnce) {
  // The line y = 1 touches the unit sphere at (0, 1, -5): discriminant exactly 0, a double
  // root at t = 5. "Negative means a miss" (the stub's contract), so zero is a hit.
  const Ray touching = make_ray(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
  const auto t = intersect_ray_sphere(touching, kCenter, kRadius);
  ASSERT_TRUE(t.has_value()) << touching << ": a tangent ray touches the sphere";
  EXPECT_NEAR(*t, 5.0f, kTolerance) << touching;
  // Just outside the tangent: a miss, whichever way the discriminant is computed.
  const Ray outside = make_ray(glm::vec3(0.0f, 1.001f, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
  const auto t_outside = intersect_ray_sphere(outside, kCenter, kRadius);
  EXPECT_FALSE(t_outside.has_value()) << outside << ": got " << describe(t_outside);
}

TEST(Sphere, OriginInsideReturnsTheFarRoot) {
  // From inside, the near root is behind the ray (t < 0): the answer is the far root. This is
  // every refracted ray travelling through a glass sphere.
  const Ray from_centre = make_ray(kCenter, glm::vec3(1.0f, 0.0f, 0.0f));
  const auto t = intersect_ray_sphere(from_centre, kCenter, kRadius);
  ASSERT_TRUE(t.has_value()) << from_centre << ": the origin is the sphere's centre";
  EXPECT_NEAR(*t, 1.0f, kTolerance) << from_centre;

  // Off-centre: origin (0, 0, 0) inside a radius-3 sphere at (0, 0, -1): roots -2 and 4.
  const Ray off_centre = make_ray(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
  const auto t_off = intersect_ray_sphere(off_centre, glm::vec3(0.0f, 0.0f, -1.0f), 3.0f);
  ASSERT_TRUE(t_off.has_value()) << off_centre << ", sphere (0, 0, -1) radius 3";
  EXPECT_NEAR(*t_off, 4.0f, kTolerance) << off_centre << ": roots are -2 and 4";
}

TEST(Sphere, SphereBehindTheRayIsNotHit) {
  // Both roots negative (-6 and -4): the line meets the sphere, the ray does not.
  const Ray ray = make_ray(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
  const auto t = intersect_ray_sphere(ray, kCenter, kRadius);
  EXPECT_FALSE(t.has_value()) << ray << ", sphere at " << kCenter << ": got " << describe(t);
}

TEST(Sphere, TMaxCutsHits) {
  const glm::vec3 down(0.0f, 0.0f, -1.0f);
  // t_max before the sphere: nothing (this is how a closer hit hides a farther sphere).
  const Ray short_ray = make_ray(glm::vec3(0.0f), down, 0.0f, 3.0f);
  const auto t_short = intersect_ray_sphere(short_ray, kCenter, kRadius);
  EXPECT_FALSE(t_short.has_value()) << short_ray << ": got " << describe(t_short);
  // t_max between the roots: the near root (4) still counts.
  const Ray middle = make_ray(glm::vec3(0.0f), down, 0.0f, 5.0f);
  const auto t_middle = intersect_ray_sphere(middle, kCenter, kRadius);
  ASSERT_TRUE(t_middle.has_value()) << middle;
  EXPECT_NEAR(*t_middle, 4.0f, kTolerance) << middle;
  // t_max exactly at the near root: excluded, and the far root is beyond it.
  const Ray exact = make_ray(glm::vec3(0.0f), down, 0.0f, 4.0f);
  const auto t_exact = intersect_ray_sphere(exact, kCenter, kRadius);
  EXPECT_FALSE(t_exact.has_value()) << exact << ": t_max is excluded; got " << describe(t_exact);
}

TEST(Sphere, TMinIsExclusiveAndSkipsToTheFarRoot) {
  const glm::vec3 down(0.0f, 0.0f, -1.0f);
  // t_min exactly at the near root (4): excluded, so the answer is the far root 6.
  const Ray at_near = make_ray(glm::vec3(0.0f), down, 4.0f);
  const auto t = intersect_ray_sphere(at_near, kCenter, kRadius);
  ASSERT_TRUE(t.has_value()) << at_near;
  EXPECT_NEAR(*t, 6.0f, kTolerance) << at_near << ": t_min is excluded";
  // t_min exactly at the far root: nothing is left.
  const Ray at_far = make_ray(glm::vec3(0.0f), down, 6.0f);
  const auto t_far = intersect_ray_sphere(at_far, kCenter, kRadius);
  EXPECT_FALSE(t_far.has_value()) << at_far << ": got " << describe(t_far);
}

TEST(Sphere, NonUnitDirectionScalesT) {
  // t is measured in units of the direction's length: doubling it halves t. Code that assumes
  // a = dot(d, d) = 1 fails here.
  const struct {
    float length;
    float expected_t;
  } cases[] = {{2.0f, 2.0f}, {0.5f, 8.0f}, {10.0f, 0.4f}};
  for (const auto& c : cases) {
    const Ray ray = make_ray(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -c.length));
    const auto t = intersect_ray_sphere(ray, kCenter, kRadius);
    ASSERT_TRUE(t.has_value()) << ray;
    EXPECT_NEAR(*t, c.expected_t, kTolerance * c.expected_t) << ray;
  }
}

TEST(Sphere, ZeroDirectionIsNoRay) {
  const Ray ray = make_ray(glm::vec3(0.0f), glm::vec3(0.0f));
  const auto t = intersect_ray_sphere(ray, kCenter, kRadius);
  EXPECT_FALSE(t.has_value()) << ray << ": got " << describe(t);
}

TEST(Sphere, SmallSphereFarAwayKeepsItsDigits) {
  // b^2 - 4ac subtracts two numbers near 4e8 whose difference is 4: in float that is 0 or
  // garbage. The stable form (Ray Tracing Gems, ch. 7) still finds t = 9999 (the near side of
  // a unit sphere 10^4 away).
  const Ray ray = make_ray(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
  const glm::vec3 far_center(0.0f, 0.0f, -1e4f);
  const auto t = intersect_ray_sphere(ray, far_center, 1.0f);
  ASSERT_TRUE(t.has_value()) << ray << ", unit sphere at " << far_center;
  EXPECT_NEAR(*t, 9999.0f, 1e-2f) << ray << ", unit sphere at " << far_center;
}

// The quadratic in double precision: the oracle for the random cases.
std::optional<double> sphere_oracle(const Ray& ray, const glm::vec3& center, float radius) {
  const glm::dvec3 o(ray.origin), d(ray.direction), c(center);
  const glm::dvec3 oc = o - c;
  const double a = glm::dot(d, d), b = 2.0 * glm::dot(oc, d);
  const double cc = glm::dot(oc, oc) - double(radius) * radius;
  const double discriminant = b * b - 4.0 * a * cc;
  if (discriminant < 0.0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  const double t0 = (-b - root) / (2.0 * a), t1 = (-b + root) / (2.0 * a);
  if (t0 > ray.t_min && t0 < ray.t_max) return t0;
  if (t1 > ray.t_min && t1 < ray.t_max) return t1;
  return std::nullopt;
}

TEST(Sphere, SeededRandomRaysAgreeWithADoubleSolve) {
  // Random spheres and rays, compared one by one with the double-precision quadratic. Cases
  // within 1e-3 of a decision boundary (grazing rays, a root near t_min) are skipped: float
  // and double may honestly disagree there.
  constexpr unsigned kSeed = 20240601u;
  SCOPED_TRACE(::testing::Message() << "std::mt19937 seed " << kSeed);
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f), radius_of(0.1f, 4.0f),
      length_of(0.2f, 5.0f);
  int hits = 0, misses = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 center(coordinate(rng), coordinate(rng), coordinate(rng));
    const float radius = radius_of(rng);
    const glm::vec3 origin(coordinate(rng), coordinate(rng), coordinate(rng));
    // Aim near the sphere so that about half the rays hit.
    const glm::vec3 target = center + 1.5f * radius * glm::vec3(coordinate(rng), coordinate(rng), coordinate(rng)) / 10.0f;
    if (glm::length(target - origin) < 1e-3f) continue;
    const Ray ray = make_ray(origin, glm::normalize(target - origin) * length_of(rng));

    const glm::dvec3 oc = glm::dvec3(origin) - glm::dvec3(center), d(ray.direction);
    const double distance_to_line = glm::length(oc - glm::dot(oc, d) / glm::dot(d, d) * d);
    if (std::abs(distance_to_line - radius) < 1e-3 * radius) continue;  // grazing
    if (std::abs(glm::length(oc) - radius) < 1e-3 * radius) continue;   // origin on the surface

    const auto expected = sphere_oracle(ray, center, radius);
    const auto actual = intersect_ray_sphere(ray, center, radius);
    ASSERT_EQ(actual.has_value(), expected.has_value())
        << "case " << i << ": " << ray << ", sphere " << center << " radius " << radius
        << ": expected " << (expected ? "t = " + std::to_string(*expected) : "no hit") << ", got "
        << describe(actual);
    if (!expected) {
      ++misses;
      continue;
    }
    ++hits;
    EXPECT_NEAR(*actual, *expected, 1e-4 * std::max(1.0, *expected))
        << "case " << i << ": " << ray << ", sphere " << center << " radius " << radius;
  }
  // The generator must exercise both outcomes, or the comparison proves little.
  EXPECT_GT(hits, 300) << "too few hits among the random cases";
  EXPECT_GT(misses, 300) << "too few misses among the random cases";
}

}  // namespace
}  // namespace raylab
