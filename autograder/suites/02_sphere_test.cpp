// Autograder suite for stage 02_sphere (20 points).
#include "grading.h"
#include "support.h"

#include "raylab/stages/02_sphere.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "02_sphere";
const bool kRegistered = register_stage(kStage, [] { (void)intersect_ray_sphere(Ray{}, glm::vec3(0, 0, -3), 1.0f); });

constexpr float kRelativeTolerance = 1e-4f;


bool close(float got, float expected) {
  return std::fabs(got - expected) <= kRelativeTolerance * std::max(1.0f, std::fabs(expected));
}

// Whether `got` is what the quadratic gives with a = 1, or t measured along the normalised
// direction: the two ways of assuming that the direction has unit length.
bool assumed_unit_direction(const Ray& ray, const glm::vec3& center, float radius, std::optional<float> got) {
  const double length = glm::length(glm::dvec3(ray.direction));
  if (!got || std::fabs(length - 1.0) < 1e-3) return false;
  const glm::dvec3 o = glm::dvec3(ray.origin) - glm::dvec3(center), d(ray.direction);
  const double b = 2.0 * glm::dot(o, d), c = glm::dot(o, o) - double(radius) * radius;
  std::vector<double> candidates;
  if (b * b - 4.0 * c >= 0.0)  // a = 1
    for (double sign : {-1.0, 1.0}) candidates.push_back((-b + sign * std::sqrt(b * b - 4.0 * c)) / 2.0);
  const double a = glm::dot(d, d);
  if (b * b - 4.0 * a * c >= 0.0)  // the right roots, but in units of the normalised direction
    for (double sign : {-1.0, 1.0}) candidates.push_back(length * (-b + sign * std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a));
  for (double t : candidates)
    if (std::fabs(*got - t) <= 1e-3 * std::max(1.0, std::fabs(t))) return true;
  return false;
}

// Whether the ray's line only touches the sphere: its distance from the centre is the radius
// (in double; the tests' tangents are exact in float), so the discriminant is 0.
bool touches(const Ray& ray, const glm::vec3& center, float radius) {
  const glm::dvec3 o = glm::dvec3(ray.origin) - glm::dvec3(center), d(ray.direction);
  const double a = glm::dot(d, d);
  if (!(a > 0.0)) return false;
  const glm::dvec3 perpendicular = o - (glm::dot(o, d) / a) * d;
  return std::fabs(glm::length(perpendicular) - double(radius)) <= 1e-9 * double(radius);
}

// Names the mistake behind a wrong answer, from the answer itself.
void diagnose(const Ray& ray, const glm::vec3& center, float radius, std::optional<float> got, std::optional<float> expected) {
  const bool origin_inside = glm::length(ray.origin - center) < radius;
  if (got && hint_if_not_finite("t", {*got}, MessageId::sphere_advice_negative_discriminant)) {
  } else if (got && (*got == ray.t_min || *got == ray.t_max)) {
    add_hint({MessageId::interval_end_counted, {{"t", std::to_string(*got)}, {"end", *got == ray.t_min ? "t_min" : "t_max"}}});
  } else if (got && !(*got > ray.t_min)) {
    add_hint({MessageId::sphere_hit_behind, {{"t", std::to_string(*got)}}});
  } else if (got && !(*got < ray.t_max)) {
    add_hint({MessageId::sphere_ignores_t_max, {{"t", std::to_string(*got)}, {"t_max", std::to_string(ray.t_max)}}});
  } else if (!got && expected && origin_inside) {
    add_hint(MessageId::sphere_misses_from_inside);
  } else if (got && expected && origin_inside && *got < *expected) {
    add_hint(MessageId::sphere_near_root_inside);
  } else if (assumed_unit_direction(ray, center, radius, got)) {
    add_hint(MessageId::sphere_assumes_unit_direction);
  } else if (got && expected) {
    if (std::fabs(*got - *expected) < 1e-2f * std::max(1.0f, std::fabs(*expected)))
      add_hint(MessageId::sphere_not_accurate);
  } else if (got && !expected) {
    add_hint(MessageId::sphere_false_hit);
  } else if (!got && expected && touches(ray, center, radius)) {
    add_hint(MessageId::sphere_tangent_missed);
  } else if (!got && expected) {
    add_hint(MessageId::sphere_misses);
  }
}

void expect_sphere(const Ray& ray, glm::vec3 center, float radius, std::optional<float> expected) {
  const std::optional<float> got = intersect_ray_sphere(ray, center, radius);
  const bool ok = got.has_value() == expected.has_value() && (!got || close(*got, *expected));
  if (!ok) diagnose(ray, center, radius, got, expected);
  if (!ok)
    add_failure({MessageId::sphere_failure,
                 {{"ray", ray_text(ray)}, {"center", gtest_text(center)}, {"radius", gtest_text(radius)},
                  {"expected", hit_text(expected)}, {"got", hit_text(got)}}});
}

GRADED_TEST(kStage, Stage02Sphere, HitInFront, 2) {
  // From the origin down -z to a unit sphere at z = -5: the near surface is at z = -4.
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -1}), {0, 0, -5}, 1.0f, 4.0f);
  // Off-centre: x = 0.6 meets the sphere where z = -5 + 0.8, at t = 4.2.
  expect_sphere(make_ray({0.6f, 0, 0}, {0, 0, -1}), {0, 0, -5}, 1.0f, 4.2f);
}

GRADED_TEST(kStage, Stage02Sphere, MissBesideTheSphere, 2) {
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -1}), {3, 0, -5}, 1.0f, std::nullopt);
  expect_sphere(make_ray({0, 1.0001f, 0}, {0, 0, -1}), {0, 0, -5}, 1.0f, std::nullopt);
}

GRADED_TEST(kStage, Stage02Sphere, SphereBehindTheRayIsMissed, 3) {
  // The whole sphere is behind the origin: both roots are negative.
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -1}), {0, 0, 5}, 1.0f, std::nullopt);
}

GRADED_TEST(kStage, Stage02Sphere, OriginInsideGetsTheFarRoot, 3) {
  // From the centre of a sphere of radius 2 the surface is 2 away, whichever way we look.
  expect_sphere(make_ray({0, 0, -5}, {0, 0, -1}), {0, 0, -5}, 2.0f, 2.0f);
  expect_sphere(make_ray({0, 0, -5}, {1, 0, 0}), {0, 0, -5}, 2.0f, 2.0f);
  // Off-centre inside, looking back towards the near side.
  expect_sphere(make_ray({0, 0, -4}, {0, 0, 1}), {0, 0, -5}, 2.0f, 1.0f);
}

GRADED_TEST(kStage, Stage02Sphere, DirectionNeedNotBeUnitLength, 2) {
  // The same ray as HitInFront with a direction twice as long: t halves.
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -2}), {0, 0, -5}, 1.0f, 2.0f);
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -0.5f}), {0, 0, -5}, 1.0f, 8.0f);
}

GRADED_TEST(kStage, Stage02Sphere, RespectsTMinAndTMax, 3) {
  // The near hit is at t = 4, the far at t = 6.
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -1}, 0.0f, 3.0f), {0, 0, -5}, 1.0f, std::nullopt);  // both beyond t_max
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -1}, 4.5f), {0, 0, -5}, 1.0f, 6.0f);               // near one before t_min
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -1}, 0.0f, 5.0f), {0, 0, -5}, 1.0f, 4.0f);
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -1}, 6.5f), {0, 0, -5}, 1.0f, std::nullopt);       // both before t_min
  // Both ends excluded: a root exactly at t_min or t_max does not count (4 and 6 are exact in float).
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -1}, 4.0f), {0, 0, -5}, 1.0f, 6.0f);
  expect_sphere(make_ray({0, 0, 0}, {0, 0, -1}, 0.0f, 4.0f), {0, 0, -5}, 1.0f, std::nullopt);
}

GRADED_TEST(kStage, Stage02Sphere, GrazingRays, 1) {
  // Just inside the silhouette: a hit near z = -5; just outside: a miss.
  const float inside = 0.999f, outside = 1.001f;
  const float depth = std::sqrt(1.0f - inside * inside);
  expect_sphere(make_ray({0, inside, 0}, {0, 0, -1}), {0, 0, -5}, 1.0f, 5.0f - depth);
  expect_sphere(make_ray({0, outside, 0}, {0, 0, -1}), {0, 0, -5}, 1.0f, std::nullopt);
  // Exactly on the silhouette: the ray touches the sphere at one point (discriminant 0), which is
  // on the surface, so it is a hit (the contract: "meets the sphere's surface").
  expect_sphere(make_ray({0, 1, 0}, {0, 0, -1}), {0, 0, -5}, 1.0f, 5.0f);
}

GRADED_TEST(kStage, Stage02Sphere, MatchesReferenceHits, 3) {
  const nlohmann::json data = load_reference_cases("02_sphere");
  int failures = 0;
  for (const nlohmann::json& c : data.at("cases")) {
    const Ray ray = make_ray(vec3_from_json(c.at("origin")), vec3_from_json(c.at("direction")),
                             c.at("t_min").get<float>(), c.at("t_max").is_null() ? kInfinity : c.at("t_max").get<float>());
    const glm::vec3 center = vec3_from_json(c.at("center"));
    const float radius = c.at("radius").get<float>();
    const std::optional<float> expected = c.at("t_hit").is_null() ? std::nullopt : std::optional<float>(c.at("t_hit").get<float>());
    const std::optional<float> got = intersect_ray_sphere(ray, center, radius);
    if (got.has_value() == expected.has_value() && (!got || close(*got, *expected))) continue;
    if (++failures <= 3) {
      diagnose(ray, center, radius, got, expected);
      add_failure({MessageId::sphere_failure_reference,
                   {{"id", c.at("id").dump()}, {"ray", ray_text(ray)}, {"center", gtest_text(center)},
                    {"radius", gtest_text(radius)}, {"expected", hit_text(expected, true)}, {"got", hit_text(got, true)}}});
    }
  }
  EXPECT_EQ(failures, 0)
      << failure_text({MessageId::failure_reference_cases,
                 {{"failures", std::to_string(failures)}, {"count", std::to_string(data.at("cases").size())},
                  {"seed", seed_shown(data)}}});
}

GRADED_TEST(kStage, Stage02Sphere, SpheresImageMatchesReference, 1) {
  expect_image_matches_reference(kStage, 0.05f, 0.005);
}

}  // namespace
}  // namespace raylab::grading
