// Autograder suite for stage 04_box (20 points).
#include "grading.h"
#include "support.h"

#include "raylab/stages/04_box.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "04_box";
const bool kRegistered = register_stage(kStage, [] {
  Ray ray;
  (void)intersect_ray_box(ray, ray_direction_inverse_of(ray), Bounds3{glm::vec3(-1), glm::vec3(1)});
});


const Bounds3 kUnitBox{glm::vec3(-1.0f), glm::vec3(1.0f)};

bool close(float got, float expected) { return std::fabs(got - expected) <= 1e-4f * std::max(1.0f, std::fabs(expected)); }

// Whether a reported entry lies beyond t_max (the mistake of starting t_exit at infinity).
bool box_beyond_t_max(const Ray& ray, std::optional<float> got) { return got && *got > ray.t_max; }

// What a slab test without the swap returns: each axis's (min - o) * inverse taken as its entry
// and (max - o) * inverse as its exit, also where the direction is negative (or -0), with NaN
// losing every comparison. Right for directions with no negative component only.
std::optional<float> unswapped_slab_test(const Ray& ray, const Bounds3& box) {
  const glm::vec3 inverse = ray_direction_inverse_of(ray);
  float t_enter = ray.t_min, t_exit = ray.t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const float t0 = (box.min[axis] - ray.origin[axis]) * inverse[axis];
    const float t1 = (box.max[axis] - ray.origin[axis]) * inverse[axis];
    if (t0 > t_enter) t_enter = t0;
    if (t1 < t_exit) t_exit = t1;
  }
  if (t_enter <= t_exit) return t_enter;
  return std::nullopt;
}
bool is_flat(const Bounds3& box) { return box.min.x == box.max.x || box.min.y == box.max.y || box.min.z == box.max.z; }
bool has_negative_component(const glm::vec3& direction) {
  return std::signbit(direction.x) || std::signbit(direction.y) || std::signbit(direction.z);
}
bool same_answer(std::optional<float> a, std::optional<float> b) {
  return a.has_value() == b.has_value() && (!a || close(*a, *b));
}

// Where the ray's line leaves the box (in double; unbounded along the ray), or nullopt when the
// line misses it: a box that the line crosses but that lies wholly before t_min is behind the ray.
std::optional<double> line_exit(const Ray& ray, const Bounds3& box) {
  double t_enter = -kInfinity, t_exit = kInfinity;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = ray.origin[axis], d = ray.direction[axis];
    if (d == 0.0) {
      if (o < box.min[axis] || o > box.max[axis]) return std::nullopt;
      continue;
    }
    const double t0 = (box.min[axis] - o) / d, t1 = (box.max[axis] - o) / d;
    t_enter = std::max(t_enter, std::min(t0, t1));
    t_exit = std::min(t_exit, std::max(t0, t1));
  }
  if (t_enter > t_exit) return std::nullopt;
  return t_exit;
}

void diagnose(const Ray& ray, const Bounds3& box, std::optional<float> got, std::optional<float> expected) {
  const bool zero_component = ray.direction.x == 0.0f || ray.direction.y == 0.0f || ray.direction.z == 0.0f;
  const std::optional<double> exit = line_exit(ray, box);
  if (got && hint_if_not_finite("t_enter", {*got}, MessageId::box_advice_nan)) {
  } else if (has_negative_component(ray.direction) && same_answer(got, unswapped_slab_test(ray, box))) {
    add_hint(MessageId::box_no_swap);
  } else if (got && !expected && (*got < ray.t_min || (exit && *exit < ray.t_min))) {
    add_hint(MessageId::box_accepts_behind);
  } else if (got && !expected && !std::isinf(ray.t_max) && box_beyond_t_max(ray, got)) {
    add_hint(MessageId::box_ignores_t_max);
  } else if (got && !expected) {
    add_hint(MessageId::box_false_hit);
  } else if (!got && expected && (*expected == ray.t_max || line_exit(ray, box) == std::optional<double>(ray.t_min))) {
    add_hint(MessageId::box_end_excluded);
  } else if (!got && expected && is_flat(box)) {
    add_hint(MessageId::box_flat_missed);
  } else if (!got && expected && zero_component) {
    add_hint(MessageId::box_misses_zero_component);
  } else if (!got && expected) {
    add_hint(MessageId::box_misses);
  } else if (got && expected && *got < ray.t_min - 1e-6f) {
    add_hint(MessageId::box_entry_not_clipped);
  } else if (got && expected && glm::length(ray.direction) != 1.0f &&
             close(*got, *expected * glm::length(ray.direction))) {
    add_hint({MessageId::box_assumes_unit_direction,  // t along the normalised direction
              {{"length", gtest_text(glm::length(ray.direction))}}});
  } else if (got && expected) {
    add_hint(MessageId::box_entry_wrong);
  }
}

Message describe(std::optional<float> t) {
  if (!t) return MessageId::value_no_hit;
  return {MessageId::value_box_entry, {{"t", std::to_string(*t)}}};
}

void expect_box(const Ray& ray, const Bounds3& box, std::optional<float> expected) {
  const std::optional<float> got = intersect_ray_box(ray, ray_direction_inverse_of(ray), box);
  const bool ok = got.has_value() == expected.has_value() && (!got || close(*got, *expected));
  if (!ok) {
    diagnose(ray, box, got, expected);
    add_failure({MessageId::box_failure,
                 {{"ray", ray_text(ray)}, {"box", box_text(box)}, {"expected", describe(expected)},
                  {"got", describe(got)}}});
  }
}

GRADED_TEST(kStage, Stage04Box, HitFromOutside, 3) {
  expect_box(make_ray({0, 0, -5}, {0, 0, 1}), kUnitBox, 4.0f);
  expect_box(make_ray({-5, -5, -5}, {1, 1, 1}), kUnitBox, 4.0f);        // diagonal, through a corner region
  expect_box(make_ray({0.5f, 0.5f, 5}, {0, 0, -2}), kUnitBox, 2.0f);    // non-unit direction: t in its units
}

GRADED_TEST(kStage, Stage04Box, MissBesideTheBox, 2) {
  expect_box(make_ray({3, 0, -5}, {0, 0, 1}), kUnitBox, std::nullopt);
  expect_box(make_ray({-5, 0, -5}, {1, 0, 0.5f}), kUnitBox, std::nullopt);  // passes the corner region
}

GRADED_TEST(kStage, Stage04Box, BoxBehindTheRayIsMissed, 3) {
  expect_box(make_ray({0, 0, 5}, {0, 0, 1}), kUnitBox, std::nullopt);
  expect_box(make_ray({3, 3, 3}, {1, 2, 3}), kUnitBox, std::nullopt);
}

GRADED_TEST(kStage, Stage04Box, OriginInsideEntersAtTMin, 2) {
  expect_box(make_ray({0, 0, 0}, {0, 0, 1}), kUnitBox, 0.0f);
  expect_box(make_ray({0.5f, 0, 0}, {1, 1, 0}, 0.25f), kUnitBox, 0.25f);
}

GRADED_TEST(kStage, Stage04Box, RespectsTMinAndTMax, 2) {
  // The box spans t in [4, 6] along this ray.
  expect_box(make_ray({0, 0, -5}, {0, 0, 1}, 0.0f, 3.0f), kUnitBox, std::nullopt);  // ends before the box
  expect_box(make_ray({0, 0, -5}, {0, 0, 1}, 6.5f), kUnitBox, std::nullopt);        // starts after it
  expect_box(make_ray({0, 0, -5}, {0, 0, 1}, 5.0f, 8.0f), kUnitBox, 5.0f);          // starts inside it
  // Both ends included: a box entered exactly at t_max, or left exactly at t_min, is hit.
  expect_box(make_ray({0, 0, -5}, {0, 0, 1}, 0.0f, 4.0f), kUnitBox, 4.0f);
  expect_box(make_ray({0, 0, -5}, {0, 0, 1}, 6.0f), kUnitBox, 6.0f);
}

GRADED_TEST(kStage, Stage04Box, ZeroDirectionComponents, 3) {
  // Axis-aligned rays: two components are +0 or -0, so two reciprocals are +-infinity.
  expect_box(make_ray({0.5f, -0.5f, -5}, {0, 0, 1}), kUnitBox, 4.0f);
  expect_box(make_ray({0.5f, -0.5f, -5}, {-0.0f, -0.0f, 1}), kUnitBox, 4.0f);
  expect_box(make_ray({5, 0.25f, 0.25f}, {-1, 0, -0.0f}), kUnitBox, 4.0f);
  expect_box(make_ray({0.5f, 2, -5}, {0, 0, 1}), kUnitBox, std::nullopt);  // parallel to y slabs, outside them
}

GRADED_TEST(kStage, Stage04Box, RaysInAFacePlane, 2) {
  // The origin lies in the plane x = 1 of a face and d.x = 0: (1 - 1) * inf is NaN. The box is
  // closed, so the ray touches it; NaN must not turn this into a miss.
  expect_box(make_ray({1, 0, -5}, {0, 0, 1}), kUnitBox, 4.0f);
  expect_box(make_ray({-1, -1, -5}, {0, -0.0f, 1}), kUnitBox, 4.0f);  // along an edge
}

GRADED_TEST(kStage, Stage04Box, FlatBoxes, 1) {
  // The box of a flat mesh has zero thickness: t_enter == t_exit must count as a hit.
  const Bounds3 flat{glm::vec3(-1, -1, 0), glm::vec3(1, 1, 0)};
  expect_box(make_ray({0, 0, -3}, {0, 0, 1}), flat, 3.0f);
  expect_box(make_ray({0.5f, 0.5f, 3}, {0.1f, 0, -1}), flat, 3.0f);
}

GRADED_TEST(kStage, Stage04Box, MatchesReferenceBoxes, 2) {
  const nlohmann::json data = load_reference_cases("04_box");
  int failures = 0;
  for (const nlohmann::json& c : data.at("cases")) {
    const Ray ray = make_ray(vec3_from_json(c.at("origin")), vec3_from_json(c.at("direction")), c.at("t_min").get<float>(),
                             c.at("t_max").is_null() ? kInfinity : c.at("t_max").get<float>());
    const Bounds3 box{vec3_from_json(c.at("min")), vec3_from_json(c.at("max"))};
    const std::optional<float> expected = c.at("t_enter").is_null() ? std::nullopt : std::optional<float>(c.at("t_enter").get<float>());
    const std::optional<float> got = intersect_ray_box(ray, ray_direction_inverse_of(ray), box);
    if (got.has_value() == expected.has_value() && (!got || close(*got, *expected))) continue;
    if (++failures <= 3) {
      diagnose(ray, box, got, expected);
      add_failure({MessageId::box_failure_reference,
                   {{"id", c.at("id").dump()}, {"ray", ray_text(ray)}, {"box", box_text(box)},
                    {"expected", describe(expected)}, {"got", describe(got)}}});
    }
  }
  EXPECT_EQ(failures, 0)
      << failure_text({MessageId::failure_reference_cases,
                 {{"failures", std::to_string(failures)}, {"count", std::to_string(data.at("cases").size())},
                  {"seed", seed_shown(data)}}});
}

}  // namespace
}  // namespace raylab::grading
