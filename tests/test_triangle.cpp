// 03_triangle: the reference intersect_ray_triangle.
//
// The contract (stages/03_triangle.h): a hit from EITHER side, inside or ON the edges, with
// t_min < t_hit < t_max, and barycentrics such that
//   origin + t_hit * direction == (1 - b1 - b2) p0 + b1 p1 + b2 p2.
//
// Most hand cases use one triangle in the plane z = -2 with right-angle corner p0:
//   p0 = (-1, -1, -2), p1 = (1, -1, -2), p2 = (-1, 1, -2)
// so a point (x, y, -2) has b1 = (x + 1) / 2 and b2 = (y + 1) / 2, exactly.
#include "raylab/stages/03_triangle.h"

#include "test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <sstream>

namespace raylab {
namespace {

using testing::vec3_near;

constexpr float kTolerance = 1e-6f;
const glm::vec3 kP0(-1.0f, -1.0f, -2.0f), kP1(1.0f, -1.0f, -2.0f), kP2(-1.0f, 1.0f, -2.0f);


// A ray straight down -z from z = 0 through the triangle's plane at (x, y): t_hit = 2.
Ray ray_down_through(float x, float y) {
  return make_ray(glm::vec3(x, y, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
}

std::string describe(const std::optional<TriangleHit>& hit) {
  std::ostringstream out;
  if (hit) out << *hit;
  else out << "no hit";
  return out.str();
}

std::string triangle_text(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  std::ostringstream out;
  out << "triangle " << p0 << ' ' << p1 << ' ' << p2;
  return out.str();
}

TEST(Triangle, InteriorHitHasExactBarycentrics) {
  // (0, -0.5) is b1 = 0.5, b2 = 0.25: different values, so swapped b1/b2 fail (the
  // checkerboard would come out mirrored).
  const Ray ray = make_ray(glm::vec3(0.0f), glm::vec3(0.0f, -0.5f, -2.0f));  // t = 1 exactly
  const auto hit = intersect_ray_triangle(ray, kP0, kP1, kP2);
  ASSERT_TRUE(hit.has_value()) << ray << ", " << triangle_text(kP0, kP1, kP2);
  EXPECT_NEAR(hit->t_hit, 1.0f, kTolerance) << ray;
  EXPECT_NEAR(hit->barycentric_b1, 0.5f, kTolerance) << ray << ": b1 is p1's weight";
  EXPECT_NEAR(hit->barycentric_b2, 0.25f, kTolerance) << ray << ": b2 is p2's weight";
}

TEST(Triangle, CentroidHasEqualBarycentrics) {
  const glm::vec3 centroid = (kP0 + kP1 + kP2) / 3.0f;
  const Ray ray = make_ray(glm::vec3(0.0f, 0.0f, 1.0f), centroid - glm::vec3(0.0f, 0.0f, 1.0f));
  const auto hit = intersect_ray_triangle(ray, kP0, kP1, kP2);
  ASSERT_TRUE(hit.has_value()) << ray;
  EXPECT_NEAR(hit->t_hit, 1.0f, kTolerance) << ray;
  EXPECT_NEAR(hit->barycentric_b1, 1.0f / 3.0f, kTolerance) << ray;
  EXPECT_NEAR(hit->barycentric_b2, 1.0f / 3.0f, kTolerance) << ray;
}

TEST(Triangle, BothFacesAreHit) {
  // No back-face culling in this course: from behind, and with the winding reversed, the
  // same point is hit with the same t.
  const Ray from_front = ray_down_through(-0.5f, 0.0f);
  const Ray from_behind = make_ray(glm::vec3(-0.5f, 0.0f, -4.0f), glm::vec3(0.0f, 0.0f, 1.0f));
  for (const Ray& ray : {from_front, from_behind}) {
    const auto hit = intersect_ray_triangle(ray, kP0, kP1, kP2);
    ASSERT_TRUE(hit.has_value()) << ray << ", " << triangle_text(kP0, kP1, kP2);
    EXPECT_NEAR(hit->t_hit, 2.0f, kTolerance) << ray;
    EXPECT_NEAR(hit->barycentric_b1, 0.25f, kTolerance) << ray;
    EXPECT_NEAR(hit->barycentric_b2, 0.5f, kTolerance) << ray;

    // Reversed winding (p0, p2, p1): the roles of b1 and b2 swap.
    const auto reversed = intersect_ray_triangle(ray, kP0, kP2, kP1);
    ASSERT_TRUE(reversed.has_value()) << ray << ", " << triangle_text(kP0, kP2, kP1);
    EXPECT_NEAR(reversed->t_hit, 2.0f, kTolerance) << ray;
    EXPECT_NEAR(reversed->barycentric_b1, 0.5f, kTolerance) << ray;
    EXPECT_NEAR(reversed->barycentric_b2, 0.25f, kTolerance) << ray;
  }
}

TEST(Triangle, JustOutsideEachEdgeIsAMiss) {
  // One point 0.1 beyond each edge, and beyond each corner: each breaks exactly one of
  // b1 >= 0, b2 >= 0, b1 + b2 <= 1 (or two, at a corner).
  const struct {
    const char* where;
    float x, y;
  } cases[] = {
      {"below edge p0-p1 (b2 < 0)", 0.0f, -1.1f},
      {"left of edge p0-p2 (b1 < 0)", -1.1f, 0.0f},
      {"beyond edge p1-p2 (b1 + b2 > 1)", 0.1f, 0.1f},
      {"beyond corner p0", -1.1f, -1.1f},
      {"beyond corner p1", 1.1f, -1.0f},
      {"beyond corner p2", -1.0f, 1.1f},
  };
  for (const auto& c : cases) {
    const Ray ray = ray_down_through(c.x, c.y);
    const auto hit = intersect_ray_triangle(ray, kP0, kP1, kP2);
    EXPECT_FALSE(hit.has_value()) << c.where << ": " << ray << ", " << triangle_text(kP0, kP1, kP2)
                                  << ": expected no hit, got " << describe(hit);
  }
}

TEST(Triangle, EdgesAndVerticesCountAsHits) {
  // "Inside or on its edges": a mesh's shared edges must not leak rays between triangles.
  // With these axis-aligned rays every barycentric below is computed exactly.
  const struct {
    const char* where;
    float x, y, b1, b2;
  } cases[] = {
      {"edge p0-p1 (b2 = 0)", 0.0f, -1.0f, 0.5f, 0.0f},
      {"edge p0-p2 (b1 = 0)", -1.0f, 0.0f, 0.0f, 0.5f},
      {"edge p1-p2 (b1 + b2 = 1)", 0.0f, 0.0f, 0.5f, 0.5f},
      {"vertex p0", -1.0f, -1.0f, 0.0f, 0.0f},
      {"vertex p1", 1.0f, -1.0f, 1.0f, 0.0f},
      {"vertex p2", -1.0f, 1.0f, 0.0f, 1.0f},
  };
  for (const auto& c : cases) {
    const Ray ray = ray_down_through(c.x, c.y);
    const auto hit = intersect_ray_triangle(ray, kP0, kP1, kP2);
    ASSERT_TRUE(hit.has_value()) << c.where << ": " << ray << ", " << triangle_text(kP0, kP1, kP2);
    EXPECT_NEAR(hit->t_hit, 2.0f, kTolerance) << c.where;
    EXPECT_NEAR(hit->barycentric_b1, c.b1, kTolerance) << c.where;
    EXPECT_NEAR(hit->barycentric_b2, c.b2, kTolerance) << c.where;
  }
}

TEST(Triangle, RayParallelToThePlaneIsAMiss) {
  // The determinant is zero: dividing by it gives inf/NaN, never a hit.
  const Ray in_plane = make_ray(glm::vec3(-5.0f, -0.5f, -2.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  const Ray above_plane = make_ray(glm::vec3(-5.0f, -0.5f, -1.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  for (const Ray& ray : {in_plane, above_plane}) {
    const auto hit = intersect_ray_triangle(ray, kP0, kP1, kP2);
    EXPECT_FALSE(hit.has_value()) << ray << ", " << triangle_text(kP0, kP1, kP2) << ": got "
                                  << describe(hit);
  }
}

TEST(Triangle, DegenerateTriangleIsNeverHitAndNeverNaN) {
  // Zero area: collinear corners (a sliver in a bad mesh) or all three at one point. A ray
  // straight through them must be a clean miss, not a hit with NaN barycentrics.
  const struct {
    const char* what;
    glm::vec3 p0, p1, p2;
  } cases[] = {
      {"collinear", {0.0f, 0.0f, -2.0f}, {1.0f, 0.0f, -2.0f}, {2.0f, 0.0f, -2.0f}},
      {"collinear along the ray", {0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, -2.0f}, {0.0f, 0.0f, -3.0f}},
      {"two corners equal", {0.0f, 0.0f, -2.0f}, {0.0f, 0.0f, -2.0f}, {1.0f, 1.0f, -2.0f}},
      {"a single point", {0.0f, 0.0f, -2.0f}, {0.0f, 0.0f, -2.0f}, {0.0f, 0.0f, -2.0f}},
  };
  const Ray rays[] = {ray_down_through(0.0f, 0.0f), ray_down_through(1.0f, 0.0f),
                      make_ray(glm::vec3(0.0f, 1.0f, -2.0f), glm::vec3(0.0f, -1.0f, 0.0f))};
  for (const auto& c : cases)
    for (const Ray& ray : rays) {
      const auto hit = intersect_ray_triangle(ray, c.p0, c.p1, c.p2);
      EXPECT_FALSE(hit.has_value()) << c.what << ": " << ray << ", "
                                    << triangle_text(c.p0, c.p1, c.p2) << ": got " << describe(hit);
    }
}

TEST(Triangle, HitsOutsideTheOpenIntervalAreRejected) {
  const Ray base = ray_down_through(-0.5f, -0.5f);  // hits at t = 2 exactly
  // Behind the ray: the plane is at t = -2.
  const Ray backwards = make_ray(base.origin, -base.direction);
  EXPECT_FALSE(intersect_ray_triangle(backwards, kP0, kP1, kP2).has_value())
      << backwards << ": the triangle is behind the origin";
  // t_min beyond the hit, and t_min exactly at it (excluded).
  for (float t_min : {2.5f, 2.0f}) {
    const Ray ray = make_ray(base.origin, base.direction, t_min);
    const auto hit = intersect_ray_triangle(ray, kP0, kP1, kP2);
    EXPECT_FALSE(hit.has_value()) << ray << ": hit at t = 2 is not > t_min; got " << describe(hit);
  }
  // t_max before the hit, and t_max exactly at it (excluded).
  for (float t_max : {1.5f, 2.0f}) {
    const Ray ray = make_ray(base.origin, base.direction, 0.0f, t_max);
    const auto hit = intersect_ray_triangle(ray, kP0, kP1, kP2);
    EXPECT_FALSE(hit.has_value()) << ray << ": hit at t = 2 is not < t_max; got " << describe(hit);
  }
  // And the interval that contains t = 2 keeps the hit (so the rejections above mean something).
  const Ray inside = make_ray(base.origin, base.direction, 1.5f, 2.5f);
  const auto hit = intersect_ray_triangle(inside, kP0, kP1, kP2);
  ASSERT_TRUE(hit.has_value()) << inside;
  EXPECT_NEAR(hit->t_hit, 2.0f, kTolerance) << inside;
}

TEST(Triangle, NonUnitDirectionScalesT) {
  const Ray ray = make_ray(glm::vec3(-0.5f, -0.5f, 0.0f), glm::vec3(0.0f, 0.0f, -4.0f));
  const auto hit = intersect_ray_triangle(ray, kP0, kP1, kP2);
  ASSERT_TRUE(hit.has_value()) << ray;
  EXPECT_NEAR(hit->t_hit, 0.5f, kTolerance) << ray << ": t is in units of the direction's length";
}

// The same equation solved in double precision by Cramer's rule: the oracle.
struct DoubleSolution {
  double t, b1, b2;
};
DoubleSolution solve_in_double(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                               const glm::vec3& p2) {
  const glm::dvec3 d(ray.direction), e1 = glm::dvec3(p1) - glm::dvec3(p0),
                   e2 = glm::dvec3(p2) - glm::dvec3(p0), s = glm::dvec3(ray.origin) - glm::dvec3(p0);
  // origin + t d = p0 + b1 e1 + b2 e2  <=>  [-d e1 e2] (t, b1, b2) = s
  const glm::dmat3 m(-d, e1, e2);
  const glm::dvec3 x = glm::inverse(m) * s;
  return {x.x, x.y, x.z};
}

TEST(Triangle, SeededRandomHitsSatisfyTheBarycentricIdentity) {
  // Random triangles and rays aimed at a random interior point. For each hit:
  //   t, b1, b2 agree with a double-precision solve, and
  //   ray.at(t) == (1 - b1 - b2) p0 + b1 p1 + b2 p2   (the contract's identity),
  // both to a tolerance relative to the scene's size. Rays aimed just outside must miss.
  // Near-degenerate triangles and grazing rays are skipped: there float cannot promise much.
  constexpr unsigned kSeed = 314159u;
  SCOPED_TRACE(::testing::Message() << "std::mt19937 seed " << kSeed);
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f), unit(0.0f, 1.0f);
  int checked_hits = 0, checked_misses = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 p0(coordinate(rng), coordinate(rng), coordinate(rng));
    const glm::vec3 p1(coordinate(rng), coordinate(rng), coordinate(rng));
    const glm::vec3 p2(coordinate(rng), coordinate(rng), coordinate(rng));
    const glm::vec3 origin = 5.0f * glm::vec3(coordinate(rng), coordinate(rng), coordinate(rng));
    float b1 = unit(rng), b2 = unit(rng);
    const bool aim_inside = i % 2 == 0;
    if (aim_inside && b1 + b2 > 1.0f) {  // fold into the triangle
      b1 = 1.0f - b1;
      b2 = 1.0f - b2;
    }
    if (!aim_inside) {  // push 0.05 to 0.5 outside one edge
      const float outside = 0.05f + 0.45f * unit(rng);
      switch (i % 3) {
        case 0: b1 = -outside; break;
        case 1: b2 = -outside; break;
        default: b2 = 1.0f - b1 + outside; break;
      }
    }
    const glm::dvec3 e1 = glm::dvec3(p1) - glm::dvec3(p0), e2 = glm::dvec3(p2) - glm::dvec3(p0);
    const glm::dvec3 normal = glm::cross(e1, e2);
    const double area = 0.5 * glm::length(normal);
    const double longest = std::max({glm::length(e1), glm::length(e2), glm::length(e2 - e1)});
    if (area < 0.05 * longest * longest) continue;  // a sliver
    const glm::dvec3 target = glm::dvec3(p0) + double(b1) * e1 + double(b2) * e2;
    const glm::dvec3 to_target = target - glm::dvec3(origin);
    if (std::abs(glm::dot(glm::normalize(to_target), glm::normalize(normal))) < 0.05) continue;  // grazing

    const Ray ray = make_ray(origin, glm::vec3(to_target * (0.5 + 2.0 * unit(rng))));
    const auto hit = intersect_ray_triangle(ray, p0, p1, p2);
    const std::string inputs = "case " + std::to_string(i) + ": " + [&] {
      std::ostringstream out;
      out << ray << ", " << triangle_text(p0, p1, p2) << ", aimed at b1 " << b1 << " b2 " << b2;
      return out.str();
    }();
    if (!aim_inside) {
      EXPECT_FALSE(hit.has_value()) << inputs << ": expected no hit, got " << describe(hit);
      ++checked_misses;
      continue;
    }
    ASSERT_TRUE(hit.has_value()) << inputs;
    ++checked_hits;
    const DoubleSolution expected = solve_in_double(ray, p0, p1, p2);
    EXPECT_NEAR(hit->t_hit, expected.t, 1e-4 * std::max(1.0, std::abs(expected.t))) << inputs;
    EXPECT_NEAR(hit->barycentric_b1, expected.b1, 1e-4) << inputs;
    EXPECT_NEAR(hit->barycentric_b2, expected.b2, 1e-4) << inputs;

    const float b0 = 1.0f - hit->barycentric_b1 - hit->barycentric_b2;
    const glm::vec3 from_barycentrics = b0 * p0 + hit->barycentric_b1 * p1 + hit->barycentric_b2 * p2;
    EXPECT_TRUE(vec3_near(ray.at(hit->t_hit), from_barycentrics, 1e-4f))
        << inputs << ": ray.at(t_hit) and the barycentric point disagree (" << *hit << ")";
  }
  EXPECT_GT(checked_hits, 500) << "too few usable random hits";
  EXPECT_GT(checked_misses, 500) << "too few usable random misses";
}

}  // namespace
}  // namespace raylab
