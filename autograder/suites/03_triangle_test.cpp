// Autograder suite for stage 03_triangle (20 points).
#include "grading.h"
#include "support.h"

#include "raylab/stages/03_triangle.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "03_triangle";
const bool kRegistered = register_stage(
    kStage, [] { (void)intersect_ray_triangle(Ray{}, glm::vec3(-1, -1, -2), glm::vec3(1, -1, -2), glm::vec3(0, 1, -2)); });

constexpr float kTolerance = 1e-4f;


bool close(float got, float expected) { return std::fabs(got - expected) <= kTolerance * std::max(1.0f, std::fabs(expected)); }

bool same_hit(const TriangleHit& a, const TriangleHit& b) {
  return close(a.t_hit, b.t_hit) && close(a.barycentric_b1, b.barycentric_b1) && close(a.barycentric_b2, b.barycentric_b2);
}

constexpr MessageId kZeroDeterminant = MessageId::triangle_advice_zero_determinant;

void diagnose(const Ray& ray, std::optional<TriangleHit> got, std::optional<TriangleHit> expected, bool back_face) {
  if (got && (hint_if_not_finite("t_hit", {got->t_hit}, kZeroDeterminant) ||
              hint_if_not_finite("barycentric_b1", {got->barycentric_b1}, kZeroDeterminant) ||
              hint_if_not_finite("barycentric_b2", {got->barycentric_b2}, kZeroDeterminant))) {
  } else if (got && (got->t_hit == ray.t_min || got->t_hit == ray.t_max)) {
    add_hint({MessageId::interval_end_counted,
              {{"t", std::to_string(got->t_hit)}, {"end", got->t_hit == ray.t_min ? "t_min" : "t_max"}}});
  } else if (got && !(got->t_hit > ray.t_min)) {
    add_hint({MessageId::triangle_hit_behind, {{"t", std::to_string(got->t_hit)}}});
  } else if (got && !(got->t_hit < ray.t_max)) {
    add_hint({MessageId::triangle_ignores_t_max, {{"t", std::to_string(got->t_hit)}}});
  } else if (got && !expected) {
    const float b0 = 1.0f - got->barycentric_b1 - got->barycentric_b2;
    if (got->barycentric_b1 < 0 || got->barycentric_b2 < 0 || b0 < 0)
      add_hint(MessageId::triangle_accepts_outside);
    else
      add_hint(MessageId::triangle_false_hit);
  } else if (got && expected) {
    if (close(got->barycentric_b1, expected->barycentric_b2) && close(got->barycentric_b2, expected->barycentric_b1))
      add_hint(MessageId::triangle_barycentrics_swapped);
    else if (!close(got->t_hit, expected->t_hit) && glm::length(ray.direction) != 1.0f &&
             close(got->t_hit, expected->t_hit * glm::length(ray.direction)))
      add_hint(MessageId::triangle_assumes_unit_direction);  // t along the normalised direction
    else if (!close(got->t_hit, expected->t_hit))
      add_hint(MessageId::triangle_t_wrong);
    else
      add_hint(MessageId::triangle_barycentrics_wrong);
  } else if (!got && expected && glm::length(ray.direction) != 1.0f &&
             !(expected->t_hit * glm::length(ray.direction) < ray.t_max)) {
    add_hint(MessageId::triangle_assumes_unit_direction);  // its t along the normalised direction is past t_max
  } else if (!got && expected && back_face) {
    add_hint(MessageId::triangle_culls_back_faces);
  } else if (!got && expected &&
             (expected->barycentric_b1 == 0.0f || expected->barycentric_b2 == 0.0f ||
              expected->barycentric_b1 + expected->barycentric_b2 == 1.0f)) {
    add_hint({MessageId::triangle_edge_excluded,
              {{"b1", gtest_text(expected->barycentric_b1)}, {"b2", gtest_text(expected->barycentric_b2)}}});
  } else if (!got && expected) {
    add_hint(MessageId::triangle_misses);
  }
}

// The value `name` of a failure text: the hit as TriangleHit prints itself, or "no hit".
MessageArg describe(const char* name, const std::optional<TriangleHit>& hit) {
  if (!hit) return {name, Message(MessageId::value_no_hit)};
  return {name, stream_text(*hit)};
}

// Fails when intersect_ray_triangle's answer is not `expected`; returns the answer.
std::optional<TriangleHit> expect_triangle(const Ray& ray, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2,
                                           std::optional<TriangleHit> expected) {
  const std::optional<TriangleHit> got = intersect_ray_triangle(ray, p0, p1, p2);
  const bool ok = got.has_value() == expected.has_value() && (!got || same_hit(*got, *expected));
  const bool back_face = glm::dot(glm::cross(p1 - p0, p2 - p0), ray.direction) > 0;
  if (!ok) diagnose(ray, got, expected, back_face);
  if (!ok)
    add_failure({MessageId::triangle_failure,
                 {{"ray", ray_text(ray)}, {"p0", gtest_text(p0)}, {"p1", gtest_text(p1)}, {"p2", gtest_text(p2)},
                  describe("expected", expected), describe("got", got)}});
  return got;
}

// A right triangle in the plane z = -2: p0 at the origin's shadow, p1 along +x, p2 along +y.
const glm::vec3 kP0(0, 0, -2), kP1(1, 0, -2), kP2(0, 1, -2);

GRADED_TEST(kStage, Stage03Triangle, HitWithBarycentrics, 3) {
  // Straight down -z at (0.2, 0.3): the point is 0.5 p0 + 0.2 p1 + 0.3 p2, at distance 2.
  expect_triangle(make_ray({0.2f, 0.3f, 0}, {0, 0, -1}), kP0, kP1, kP2, TriangleHit{2.0f, 0.2f, 0.3f});
  // The same with a non-unit direction: t is in units of the direction.
  expect_triangle(make_ray({0.25f, 0.5f, 0}, {0, 0, -4}), kP0, kP1, kP2, TriangleHit{0.5f, 0.25f, 0.5f});
}

GRADED_TEST(kStage, Stage03Triangle, BothFacesAreHit, 2) {
  // From behind (z = -4 looking +z) the winding is clockwise: still a hit.
  expect_triangle(make_ray({0.2f, 0.3f, -4}, {0, 0, 1}), kP0, kP1, kP2, TriangleHit{2.0f, 0.2f, 0.3f});
}

GRADED_TEST(kStage, Stage03Triangle, PointsOutsideEachEdgeAreMissed, 4) {
  expect_triangle(make_ray({-0.1f, 0.3f, 0}, {0, 0, -1}), kP0, kP1, kP2, std::nullopt);   // beyond edge p0-p2 (b1 < 0)
  expect_triangle(make_ray({0.3f, -0.1f, 0}, {0, 0, -1}), kP0, kP1, kP2, std::nullopt);   // beyond edge p0-p1 (b2 < 0)
  expect_triangle(make_ray({0.6f, 0.6f, 0}, {0, 0, -1}), kP0, kP1, kP2, std::nullopt);    // beyond the hypotenuse (b1 + b2 > 1)
  expect_triangle(make_ray({1.5f, 0.1f, 0}, {0, 0, -1}), kP0, kP1, kP2, std::nullopt);    // b1 > 1
}

GRADED_TEST(kStage, Stage03Triangle, EdgesAndVerticesCountAsInside, 2) {
  expect_triangle(make_ray({0.5f, 0.5f, 0}, {0, 0, -1}), kP0, kP1, kP2, TriangleHit{2.0f, 0.5f, 0.5f});
  expect_triangle(make_ray({0.5f, 0.0f, 0}, {0, 0, -1}), kP0, kP1, kP2, TriangleHit{2.0f, 0.5f, 0.0f});
  expect_triangle(make_ray({1.0f, 0.0f, 0}, {0, 0, -1}), kP0, kP1, kP2, TriangleHit{2.0f, 1.0f, 0.0f});
  // Each edge and corner once, so that any one strict comparison (b1 > 0, b2 > 0, b1 + b2 < 1)
  // misses one: the edge p0-p2 (b1 = 0), and the corners p0 and p2.
  expect_triangle(make_ray({0.0f, 0.5f, 0}, {0, 0, -1}), kP0, kP1, kP2, TriangleHit{2.0f, 0.0f, 0.5f});
  expect_triangle(make_ray({0.0f, 0.0f, 0}, {0, 0, -1}), kP0, kP1, kP2, TriangleHit{2.0f, 0.0f, 0.0f});
  expect_triangle(make_ray({0.0f, 1.0f, 0}, {0, 0, -1}), kP0, kP1, kP2, TriangleHit{2.0f, 0.0f, 1.0f});
}

GRADED_TEST(kStage, Stage03Triangle, TriangleBehindTheRayIsMissed, 2) {
  expect_triangle(make_ray({0.2f, 0.3f, -3}, {0, 0, -1}), kP0, kP1, kP2, std::nullopt);
}

GRADED_TEST(kStage, Stage03Triangle, RespectsTMinAndTMax, 2) {
  expect_triangle(make_ray({0.2f, 0.3f, 0}, {0, 0, -1}, 0.0f, 1.5f), kP0, kP1, kP2, std::nullopt);
  expect_triangle(make_ray({0.2f, 0.3f, 0}, {0, 0, -1}, 2.5f), kP0, kP1, kP2, std::nullopt);
  expect_triangle(make_ray({0.2f, 0.3f, 0}, {0, 0, -1}, 1.5f, 2.5f), kP0, kP1, kP2, TriangleHit{2.0f, 0.2f, 0.3f});
  // Both ends excluded: a hit exactly at t_min or t_max does not count (t = 2 is exact in float).
  expect_triangle(make_ray({0.2f, 0.3f, 0}, {0, 0, -1}, 2.0f), kP0, kP1, kP2, std::nullopt);
  expect_triangle(make_ray({0.2f, 0.3f, 0}, {0, 0, -1}, 0.0f, 2.0f), kP0, kP1, kP2, std::nullopt);
}

GRADED_TEST(kStage, Stage03Triangle, ParallelRaysAndDegenerateTriangles, 2) {
  struct Case {
    Ray ray;
    glm::vec3 p0, p1, p2;
  };
  const Case cases[] = {
      // In the triangle's plane, and above it, parallel: no hit (and no division by zero).
      {make_ray({-1, 0.2f, -2}, {1, 0, 0}), kP0, kP1, kP2},
      {make_ray({-1, 0.2f, 0}, {1, 0, 0}), kP0, kP1, kP2},
      // Zero area: three points on a line, and all three the same.
      {make_ray({0.5f, 0, 0}, {0, 0, -1}), kP0, kP1, glm::vec3(2, 0, -2)},
      {make_ray({0, 0, 0}, {0, 0, -1}), kP0, kP0, kP0},
  };
  bool hit = false;
  for (const Case& c : cases) hit = expect_triangle(c.ray, c.p0, c.p1, c.p2, std::nullopt).has_value() || hit;
  if (hit) add_hint(MessageId::triangle_degenerate_hit);
}

GRADED_TEST(kStage, Stage03Triangle, MatchesReferenceHits, 2) {
  const nlohmann::json data = load_reference_cases("03_triangle");
  int failures = 0;
  for (const nlohmann::json& c : data.at("cases")) {
    const Ray ray = make_ray(vec3_from_json(c.at("origin")), vec3_from_json(c.at("direction")), c.at("t_min").get<float>(),
                             c.at("t_max").is_null() ? kInfinity : c.at("t_max").get<float>());
    const glm::vec3 p0 = vec3_from_json(c.at("p0")), p1 = vec3_from_json(c.at("p1")), p2 = vec3_from_json(c.at("p2"));
    std::optional<TriangleHit> expected;
    if (!c.at("hit").is_null())
      expected = TriangleHit{c["hit"].at(0).get<float>(), c["hit"].at(1).get<float>(), c["hit"].at(2).get<float>()};
    const std::optional<TriangleHit> got = intersect_ray_triangle(ray, p0, p1, p2);
    if (got.has_value() == expected.has_value() && (!got || same_hit(*got, *expected))) continue;
    if (++failures <= 3) {
      diagnose(ray, got, expected, glm::dot(glm::cross(p1 - p0, p2 - p0), ray.direction) > 0);
      add_failure({MessageId::triangle_failure_reference,
                   {{"id", c.at("id").dump()}, {"ray", ray_text(ray)}, {"p0", gtest_text(p0)}, {"p1", gtest_text(p1)},
                    {"p2", gtest_text(p2)}, describe("expected", expected), describe("got", got)}});
    }
  }
  EXPECT_EQ(failures, 0)
      << failure_text({MessageId::failure_reference_cases,
                 {{"failures", std::to_string(failures)}, {"count", std::to_string(data.at("cases").size())},
                  {"seed", seed_shown(data)}}});
}

GRADED_TEST(kStage, Stage03Triangle, WhittedImageMatchesReference, 1) {
  // The floor's checkerboard is read through your barycentrics: swapped ones mirror it.
  expect_image_matches_reference(kStage, 0.05f, 0.005);
}

}  // namespace
}  // namespace raylab::grading
