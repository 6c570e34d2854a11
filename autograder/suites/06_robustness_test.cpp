// Autograder suite for the bonus stage 06_robustness (24 points): your kernels on inputs
// chosen to break float arithmetic. Handouts: docs/accuracy.md, docs/02_sphere.md (section 3)
// and docs/03b_watertight.md.
//
//   - intersect_ray_sphere (stage 02) on small spheres far away and huge spheres seen from
//     close by, against the EXACT answer for the float inputs (long double, checked in by the
//     regenerate tool): the textbook quadratic loses digits to catastrophic cancellation;
//   - intersect_ray_triangle_watertight (stage 03b): the same answers as stage 03, zero rays
//     slipping through closed meshes at their shared edges and vertices, and no NaN from
//     degenerate triangles or rays parallel to them, and no hit on the surface a ray starts on
//     (shadow acne: the t error bound, docs/03b_watertight.md section 4). Your stage 03
//     (Moller-Trumbore) leak count is shown as a note, for comparison (0 points);
//   - intersect_ray_box (stage 04) on rays aimed exactly at box edges, against the exact answer:
//     without Ize's conservative exit factor, rounding loses boxes the ray touches.
#include "04_box_calls.h"
#include "06_robustness_calls.h"
#include "grading.h"
#include "support.h"

#include "raylab/error.h"
#include "raylab/mesh_generator.h"
#include "raylab/shading.h"
#include "raylab/stages/02_sphere.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/stages/03b_watertight.h"
#include "raylab/stages/04_box.h"
#include "raylab/testkit/leaks.h"
#include "raylab/testkit/oracles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "06_robustness";
// Not attempted only while every function graded here is a stub: a student who has written
// the sphere (stage 02) and the box test (stage 04) but not 03b is graded on those, and
// only the watertight tests are marked not attempted.
void probe_written_functions() {
  std::exception_ptr not_implemented;
  bool any_written = false;
  auto probe = [&](auto&& call) {
    try {
      call();
      any_written = true;
    } catch (const NotImplemented&) {
      not_implemented = std::current_exception();
    } catch (...) {
      any_written = true;  // written, and wrong: the tests say how
    }
  };
  probe([] { (void)intersect_ray_sphere(Ray{}, glm::vec3(0, 0, -3), 1.0f); });
  probe([] { (void)intersect_ray_box(Ray{}, glm::vec3(kInfinity), Bounds3{glm::vec3(-1), glm::vec3(1)}); });
  probe([] { (void)intersect_ray_triangle_watertight(Ray{}, glm::vec3(-1, -1, -2), glm::vec3(1, -1, -2), glm::vec3(0, 1, -2)); });
  if (!any_written && not_implemented) std::rethrow_exception(not_implemented);
}
const bool kRegistered = register_stage(kStage, probe_written_functions);

// The reference's error on these cases is below 3e-6; the textbook quadratic's reaches 1e-3.
constexpr double kSphereRelativeTolerance = 1e-5;

constexpr MessageId kCancellationHint = MessageId::robust_cancellation;

Ray make_ray(glm::vec3 origin, glm::vec3 direction) {
  Ray ray;
  ray.origin = origin;
  ray.direction = direction;
  return ray;
}

// Whether a sphere answer is the exact one for its float inputs, to kSphereRelativeTolerance;
// `error` (out) is its relative error when both are hits.
bool sphere_answer_right(const std::optional<float>& got, const std::optional<long double>& exact, double* error = nullptr) {
  if (got.has_value() != exact.has_value()) return false;
  if (!got) return true;
  const double relative = std::fabs(double(*got) - double(*exact)) / std::fabs(double(*exact));
  if (error) *error = std::isfinite(relative) ? relative : 1e30;
  return relative <= kSphereRelativeTolerance;
}

// The well-conditioned twin of a case: the same sphere and the same direction vector, the ray's
// line at the same distance from the centre (so the same hit or miss), but started 3 radii before
// the centre instead of far away or on the surface. Stage 02's contract decides it without any
// rounding trouble, so a wrong answer there is a mistake stage 02 grades, not a lack of precision;
// such cases are not judged here (a mistake costs points at its own stage only).
Ray well_conditioned_twin(const Ray& ray, const glm::vec3& center, float radius) {
  const glm::dvec3 direction = glm::normalize(glm::dvec3(ray.direction));
  const glm::dvec3 from_center = glm::dvec3(ray.origin) - glm::dvec3(center);
  const glm::dvec3 across = from_center - glm::dot(from_center, direction) * direction;
  return make_ray(glm::vec3(glm::dvec3(center) + across - 3.0 * double(radius) * direction), ray.direction);
}

void check_sphere_cases(const std::string& kind) {
  const nlohmann::json data = load_reference_cases("06_robustness");
  int checked = 0, failures = 0, not_judged = 0, hits_judged = 0;
  double worst = 0.0;
  for (const nlohmann::json& c : data.at("cases")) {
    if (c.at("kind") != kind) continue;
    ++checked;
    const Ray ray = make_ray(vec3_from_json(c.at("origin")), vec3_from_json(c.at("direction")));
    const glm::vec3 center = vec3_from_json(c.at("center"));
    const float radius = c.at("radius").get<float>();
    const bool expected_hit = !c.at("t_exact").is_null();
    const double expected_t = expected_hit ? c.at("t_exact").get<double>() : 0.0;
    // The twin first: judged only where it is right (a near-tangent twin, which a correct float
    // kernel may decide either way, judges nothing either).
    const Ray twin = well_conditioned_twin(ray, center, radius);
    long double twin_margin = 0;
    const std::optional<long double> twin_exact = testkit::exact_sphere_hit(twin, center, radius, &twin_margin);
    if (twin_margin < 1e-3L || !sphere_answer_right(intersect_ray_sphere(twin, center, radius), twin_exact)) {
      ++not_judged;
      continue;
    }
    hits_judged += expected_hit;
    const std::optional<float> got = intersect_ray_sphere(ray, center, radius);
    double error = 0.0;
    const bool ok = sphere_answer_right(got, expected_hit ? std::optional<long double>(expected_t) : std::nullopt, &error);
    worst = std::max(worst, error);
    if (ok) continue;
    if (++failures <= 3) {
      const Message expected = expected_hit ? Message(MessageId::value_t, {{"t", std::to_string(expected_t)}})
                                            : Message(MessageId::value_no_hit);
      add_failure({MessageId::robust_failure_sphere,
                   {{"id", c.at("id").dump()}, {"kind", kind}, {"ray", ray_text(ray)}, {"center", gtest_text(center)},
                    {"radius", gtest_text(radius)}, {"expected", expected},
                    {"tolerance", gtest_text(kSphereRelativeTolerance)}, {"got", hit_text(got)}}});
    }
  }
  if (failures > 0) add_hint(kCancellationHint);
  char worst_text[32];
  std::snprintf(worst_text, sizeof worst_text, "%.2e", worst);
  add_note({MessageId::note_sphere_error,
            {{"kind", kind}, {"worst", worst_text}, {"count", std::to_string(checked - not_judged)}}});
  if (not_judged > 0)
    add_note({MessageId::note_sphere_not_judged, {{"count", std::to_string(not_judged)}, {"of", std::to_string(checked)}}});
  // A sphere that finds no hit of the well-conditioned twins leaves nothing to judge here, and
  // earns nothing, as a stub does (docs/instructors.md, "Each stage graded on its own").
  if (hits_judged == 0) {
    add_failure({MessageId::robust_failure_sphere_nothing_judged, {{"kind", kind}}});
    return;
  }
  EXPECT_EQ(failures, 0)
      << failure_text({MessageId::robust_failure_spheres_wrong,
                 {{"failures", std::to_string(failures)}, {"count", std::to_string(checked - not_judged)}, {"kind", kind},
                  {"seed", seed_shown(data)}}});
}

GRADED_TEST(kStage, Stage06Robustness, SmallSpheresFarAway, 4) { check_sphere_cases("far_tiny"); }

GRADED_TEST(kStage, Stage06Robustness, HugeSpheresSeenFromNearby, 3) { check_sphere_cases("huge_near"); }

// ---- Watertight triangles ---------------------------------------------------------------

bool close(float got, float expected) { return std::fabs(got - expected) <= 1e-4f * std::max(1.0f, std::fabs(expected)); }

GRADED_TEST(kStage, Stage06Robustness, WatertightMatchesStage03Answers, 3) {
  // The same contract as stage 03: the same hits, t and barycentrics on stage 03's cases.
  const nlohmann::json data = load_reference_cases("03_triangle");
  int failures = 0, misses[2] = {0, 0};
  bool normalised = false;
  for (const nlohmann::json& c : data.at("cases")) {
    Ray ray = make_ray(vec3_from_json(c.at("origin")), vec3_from_json(c.at("direction")));
    ray.t_min = c.at("t_min").get<float>();
    ray.t_max = c.at("t_max").is_null() ? kInfinity : c.at("t_max").get<float>();
    const glm::vec3 p0 = vec3_from_json(c.at("p0")), p1 = vec3_from_json(c.at("p1")), p2 = vec3_from_json(c.at("p2"));
    const std::optional<TriangleHit> got = intersect_ray_triangle_watertight(ray, p0, p1, p2);
    const bool expected = !c.at("hit").is_null();
    bool ok = got.has_value() == expected;
    if (ok && got)
      ok = close(got->t_hit, c["hit"].at(0).get<float>()) && close(got->barycentric_b1, c["hit"].at(1).get<float>()) &&
           close(got->barycentric_b2, c["hit"].at(2).get<float>());
    if (ok) continue;
    // (Stage 03's hints where the mistake is one that stage 03 names too.)
    const float length = glm::length(ray.direction);
    const float expected_t = expected ? c["hit"].at(0).get<float>() : 0.0f;
    const bool facing_along = glm::dot(glm::cross(p1 - p0, p2 - p0), ray.direction) > 0.0f;  // by its winding
    const bool t_normalised = length != 1.0f && got && expected && close(got->t_hit, expected_t * length);
    normalised = normalised || t_normalised;  // (its misses come from comparing t_max with such a t)
    if (!got && expected) {
      ++misses[facing_along ? 1 : 0];  // named after the loop: culling when every miss faces one way
    } else if (failures < 3) {         // a hint for each failure shown
      if (t_normalised)
        add_hint(MessageId::triangle_assumes_unit_direction);  // t along the normalised direction
      else if (got && !expected && !(got->t_hit < ray.t_max))
        add_hint({MessageId::triangle_ignores_t_max, {{"t", std::to_string(got->t_hit)}}});
      else if (got && expected && close(got->barycentric_b1, c["hit"].at(2).get<float>()) &&
               close(got->barycentric_b2, c["hit"].at(1).get<float>()))
        add_hint(MessageId::robust_barycentrics_swapped);
      else if (got && expected && close(got->t_hit, expected_t))
        add_hint(MessageId::robust_barycentrics_wrong);
      else if (got && !expected)
        add_hint(MessageId::robust_false_hits);
    }
    if (++failures <= 3) {
      const MessageArg got_text = got ? MessageArg("got", stream_text(*got)) : MessageArg("got", Message(MessageId::value_no_hit));
      const MessageArg expected_text = expected ? MessageArg("expected", c.at("hit").dump())
                                                : MessageArg("expected", Message(MessageId::value_no_hit));
      add_failure({MessageId::robust_failure_stage03_case,
                   {{"id", c.at("id").dump()}, {"ray", ray_text(ray)}, {"p0", gtest_text(p0)}, {"p1", gtest_text(p1)},
                    {"p2", gtest_text(p2)}, expected_text, got_text}});
    }
  }
  if (misses[0] + misses[1] > 0 && !normalised)
    add_hint(misses[0] == 0 || misses[1] == 0 ? MessageId::triangle_culls_back_faces : MessageId::robust_misses);
  EXPECT_EQ(failures, 0)
      << failure_text({MessageId::robust_failure_stage03_count,
                 {{"failures", std::to_string(failures)}, {"count", std::to_string(data.at("cases").size())}}});
}

// The closed meshes of the leak tests (raylab/testkit/leaks.h), named for the report.
struct NamedMesh {
  testkit::ClosedMesh mesh;
  Message name;  // "a sphere of 1280 triangles", in either language
};
NamedMesh named(testkit::ClosedMesh mesh, MessageId description) {
  const std::string triangles = std::to_string(mesh.triangle_count());
  return {std::move(mesh), {description, {{"triangles", triangles}}}};
}

NamedMesh icosphere(int levels, float radius, glm::vec3 center) {
  return named(testkit::closed_icosphere(levels, radius, center), MessageId::robust_mesh_sphere);
}

NamedMesh grid_cube(int n, float half, glm::vec3 center) {
  return named(testkit::closed_grid_cube(n, half, center), MessageId::robust_mesh_cube);
}

// testkit::count_leaks with your triangle test, called in the stage server in batches
// (06_robustness_calls.h): every ray against the triangles around the two vertices of its edge, then
// each ray that none of those hits against every triangle.
testkit::LeakCount count_leaks(const testkit::ClosedMesh& mesh, TriangleFunction test, int rays, std::uint32_t seed) {
  std::vector<protocol::Triangle> triangles;
  for (std::size_t t = 0; t * 3 + 2 < mesh.indices.size(); ++t)
    triangles.push_back({mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                         mesh.positions[mesh.indices[3 * t + 2]]});
  Pcg32 random(seed, testkit::stream_of("leak rays"));
  return testkit::count_leaks(mesh, static_cast<std::uint64_t>(rays), random,
                              [&](const std::vector<Ray>& batch, const std::vector<std::vector<std::uint32_t>>& candidates) {
                                const auto hit_lists = triangles_hit(test, triangles, batch, candidates);
                                std::vector<bool> any(hit_lists.size());
                                for (std::size_t r = 0; r < hit_lists.size(); ++r) any[r] = !hit_lists[r].empty();
                                return any;
                              });
}

constexpr int kLeakRays = 100000;

GRADED_TEST(kStage, Stage06Robustness, NoRayLeaksThroughClosedMeshes, 6) {
  constexpr int kRays = kLeakRays;
  const NamedMesh meshes[] = {icosphere(3, 1.0f, glm::vec3(0.1f, -0.2f, 0.3f)), grid_cube(8, 1.0f, glm::vec3(0.0f))};
  for (const NamedMesh& mesh : meshes) {
    const testkit::LeakCount count = count_leaks(mesh.mesh, &intersect_ray_triangle_watertight, kRays, 6);
    const std::uint64_t leaks = count.leaks;
    const Ray first_leak = count.first_leak.value_or(Ray());
    add_note({MessageId::note_watertight_leaks,
              {{"mesh", mesh.name}, {"leaks", std::to_string(leaks)}, {"rays", std::to_string(kRays)}}});
    if (leaks > 0) {
      // Rounding at shared edges leaks a few rays in a thousand at most; half of them or more is a
      // test that misses whole triangles (from behind: culling).
      if (2 * leaks >= static_cast<std::uint64_t>(kRays))
        add_hint({MessageId::robust_leaks_most, {{"leaks", std::to_string(leaks)}, {"rays", std::to_string(kRays)}}});
      else
        add_hint(MessageId::robust_leaks);
      add_failure({MessageId::robust_failure_leaks,
                   {{"mesh", mesh.name}, {"leaks", std::to_string(leaks)}, {"rays", std::to_string(kRays)},
                    {"ray", ray_text(first_leak)}}});
    }
  }
}

// A zero direction, a ray parallel to the triangle's plane and a triangle without area hit
// nothing (for the parallel rays and the triangles without area det is exactly 0, in any
// rounding; the ray 1e-7 radians from the plane meets it only at its origin, t = 0, which is not
// above t_min); a triangle with a corner at infinity or NaN may be hit or not, but never with a NaN
// or at t <= t_min.
GRADED_TEST(kStage, Stage06Robustness, DegenerateAndParallelInputsHitNothing, 2) {
  const glm::vec3 p0(0, 0, -2), p1(1, 0, -2), p2(0, 1, -2);
  struct Input {
    const char* what;
    Ray ray;
    glm::vec3 a, b, c;
    bool hit_allowed = false;  // a finite hit is acceptable
  };
  auto ray_of = [](glm::vec3 origin, glm::vec3 direction) { return make_ray(origin, direction); };
  const Input inputs[] = {
      {"zero direction", ray_of({0.2f, 0.2f, 0}, {0, 0, 0}), p0, p1, p2},
      {"ray in the triangle's plane", ray_of({-1, 0.2f, -2}, {1, 0, 0}), p0, p1, p2},
      {"ray along an edge", ray_of({-1, 0, -2}, {1, 0, 0}), p0, p1, p2},
      {"parallel ray above the plane", ray_of({-1, 0.2f, 0}, {1, 0, 0}), p0, p1, p2},
      {"ray 1e-7 radians from the plane", ray_of({-1, 0.2f, -2}, {1, 0, 1e-7f}), p0, p1, p2},
      {"all three corners equal", ray_of({0, 0, 0}, {0, 0, -1}), p0, p0, p0},
      {"two corners equal", ray_of({0.3f, 0, 0}, {0, 0, -1}), p0, p1, p1},
      {"three corners on a line", ray_of({0.5f, 0, 0}, {0, 0, -1}), p0, p1, glm::vec3(2, 0, -2)},
      {"infinite corner", ray_of({0.2f, 0.2f, 0}, {0, 0, -1}), p0, glm::vec3(kInfinity, 0, -2), p2, true},
      {"NaN corner", ray_of({0.2f, 0.2f, 0}, {0, 0, -1}), p0, p1, glm::vec3(std::nanf(""), 1, -2), true},
  };
  for (const Input& input : inputs) {
    const std::optional<TriangleHit> got = intersect_ray_triangle_watertight(input.ray, input.a, input.b, input.c);
    if (!got) continue;
    const bool finite = std::isfinite(got->t_hit) && std::isfinite(got->barycentric_b1) && std::isfinite(got->barycentric_b2);
    if (finite && input.hit_allowed && got->t_hit > input.ray.t_min) continue;
    if (!finite) add_hint(MessageId::robust_degenerate_nan);
    else if (!input.hit_allowed) add_hint(MessageId::robust_degenerate_hit);
    add_failure({input.hit_allowed ? MessageId::robust_failure_degenerate_finite : MessageId::robust_failure_degenerate,
                 {{"what", input.what}, {"ray", ray_text(input.ray)}, {"p0", gtest_text(input.a)},
                  {"p1", gtest_text(input.b)}, {"p2", gtest_text(input.c)}, {"got", gtest_text(*got)}}});
  }
}

// Shadow acne: a ray that starts on a triangle, as the renderer starts a shadow or reflected
// ray (the hit point from barycentrics, moved off the surface by its error bound), and
// leaves it must not hit that triangle again: its plane is behind the origin. A hit at a
// tiny positive t is the surface the ray starts on, found again by a t that rounded the
// wrong way: the speckled self-shadowing of a large floor. The t error bound rejects it.
GRADED_TEST(kStage, Stage06Robustness, NoHitOnTheSurfaceTheRayStartsOn, 3) {
  constexpr int kRays = 20000;
  Pcg32 random(606, testkit::stream_of("acne rays"));
  // Each ray leaving its triangle, with the triangle: tested in the stage server in one request.
  std::vector<TriangleTestArguments> leaving;
  for (int r = 0; r < kRays; ++r) {
    // A large floor or wall: an axis-aligned triangle (extent `scale` in two axes) whose plane
    // is close to the world origin along the third (a floor at y = -0.004 in bunny.json).
    // There the hit point's error, and so the renderer's offset, is tiny, while the error of
    // t grows with the triangle's size: the case where a t that rounds the wrong way shows.
    const float scale = r % 2 == 0 ? 30.0f : 300.0f;
    const int normal_axis = testkit::random_integer(random, 0, 2);
    const float plane = r % 3 == 0 ? 0.0f : random.uniform(-0.01f, 0.01f);
    glm::vec3 corners[3];
    for (glm::vec3& corner : corners) {
      corner = testkit::random_vec3(random, -1, 1) * scale;
      corner[normal_axis] = plane;
    }
    const glm::vec3 p0 = corners[0], p1 = corners[1], p2 = corners[2];
    const glm::vec3 normal = glm::cross(p1 - p0, p2 - p0);
    if (!(glm::length(normal) > 1e-3f * scale * scale)) continue;
    float b1 = random.uniform(0, 1), b2 = random.uniform(0, 1);
    if (b1 + b2 > 1.0f) {
      b1 = 1.0f - b1;
      b2 = 1.0f - b2;
    }
    // The hit point and its error bound as the renderer computes them (geometry.cpp), and the
    // ray leaving it as the renderer starts it: offset by that bound to the side it leaves
    // towards, so that the triangle's plane is behind the origin.
    const float b0 = 1.0f - b1 - b2;
    SurfaceHit start;
    start.point = b0 * p0 + b1 * p1 + b2 * p2;
    start.point_error = gamma_bound(7) * (glm::abs(b0 * p0) + glm::abs(b1 * p1) + glm::abs(b2 * p2));
    start.geometric_normal = glm::normalize(normal);
    const glm::vec3 direction = testkit::random_vec3(random, -1, 1);
    // Leaving the surface at 3 degrees or more, to either side.
    const float cosine = glm::dot(glm::normalize(direction), start.geometric_normal);
    if (!(std::fabs(cosine) > 0.05f) || glm::length(direction) < 0.1f) continue;
    leaving.emplace_back(spawn_ray(start, direction), p0, p1, p2);
  }
  const std::vector<std::optional<TriangleHit>> hits = intersect_ray_triangle_watertight_each(leaving);
  const int tested = static_cast<int>(leaving.size());
  int acne = 0;
  std::size_t first = 0;
  for (std::size_t r = 0; r < hits.size(); ++r)
    if (hits[r] && ++acne == 1) first = r;
  add_note({MessageId::note_shadow_acne, {{"acne", std::to_string(acne)}, {"rays", std::to_string(tested)}}});
  if (acne > 0) {
    const auto& [ray, p0, p1, p2] = leaving[first];
    add_hint(MessageId::robust_shadow_acne);
    add_failure({MessageId::robust_failure_acne,
                 {{"acne", gtest_text(acne)}, {"rays", gtest_text(tested)}, {"ray", ray_text(ray)},
                  {"p0", gtest_text(p0)}, {"p1", gtest_text(p1)}, {"p2", gtest_text(p2)},
                  {"t", gtest_text(hits[first]->t_hit)}}});
  }
}

// Rays aimed exactly at a point on an edge of a box touch the box; in float the computed exit
// can round to just below the entry, and the plain slab test then reports a miss. Checked
// against long double; the reference's Ize factor (docs/04_box.md, section 4) loses none.
GRADED_TEST(kStage, Stage06Robustness, BoxTestKeepsBoxesTheRayTouches, 3) {
  constexpr int kRays = 100000;
  Pcg32 random(404, testkit::stream_of("box edge rays"));
  // Each ray that touches its box, with the box: tested in the stage server in one request.
  std::vector<BoxTestArguments> touching;
  for (int r = 0; r < kRays; ++r) {
    Bounds3 box;
    box.extend(testkit::random_vec3(random, -10, 10));
    box.extend(testkit::random_vec3(random, -10, 10));
    // A point on one of the box's 12 edges: two coordinates at bounds, one inside.
    const int free_axis = testkit::random_integer(random, 0, 2);
    glm::vec3 target;
    for (int axis = 0; axis < 3; ++axis)
      target[axis] = axis == free_axis ? random.uniform(box.min[axis], box.max[axis])
                                       : (testkit::random_integer(random, 0, 1) ? box.max[axis] : box.min[axis]);
    Ray ray = make_ray(testkit::random_vec3(random, -30, 30), glm::vec3(0.0f));
    if (box.contains(ray.origin)) continue;
    ray.direction = (target - ray.origin) * random.uniform(0.5f, 2.0f);
    // The exact answer for these float inputs, in long double (entry <= exit: the box is hit).
    long double t_enter = 0.0L, t_exit = 1e30L;
    for (int axis = 0; axis < 3; ++axis) {
      const long double origin = ray.origin[axis], direction = ray.direction[axis];
      if (direction == 0.0L) {
        if (origin < box.min[axis] || origin > box.max[axis]) t_enter = 1e31L;
        continue;
      }
      long double t_near = (box.min[axis] - origin) / direction, t_far = (box.max[axis] - origin) / direction;
      if (t_near > t_far) std::swap(t_near, t_far);
      t_enter = std::max(t_enter, t_near);
      t_exit = std::min(t_exit, t_far);
    }
    if (!(t_exit >= t_enter - 1e-12L * std::max(1.0L, std::fabs(t_enter)))) continue;  // a true miss: not graded here
    touching.emplace_back(ray, ray_direction_inverse_of(ray), box);
  }
  // Each ray's well-conditioned twin: the same ray and a box grown by a tenth of its size on every
  // side, through whose inside the ray passes (the edge point is well inside it), so that stage
  // 04's contract decides it without any rounding trouble. A ray whose twin your box test misses
  // shows a mistake that stage 04 grades (a missing swap, say), not a lack of precision: it is not
  // judged here (a mistake costs points at its own stage only).
  std::vector<BoxTestArguments> twins = touching;
  for (BoxTestArguments& twin : twins) {
    Bounds3& box = std::get<2>(twin);
    const glm::vec3 margin = glm::max(0.1f * (box.max - box.min), glm::vec3(0.01f));
    box = Bounds3{box.min - margin, box.max + margin};
  }
  const std::vector<std::optional<float>> twin_hits = intersect_ray_box_each(twins);
  const std::vector<std::optional<float>> hits = intersect_ray_box_each(touching);
  int lost = 0, judged = 0;
  std::size_t first = 0;
  for (std::size_t r = 0; r < hits.size(); ++r) {
    if (!twin_hits[r]) continue;
    ++judged;
    if (!hits[r] && ++lost == 1) first = r;
  }
  const int boxes = static_cast<int>(touching.size());
  add_note({MessageId::note_box_edge, {{"lost", std::to_string(lost)}, {"boxes", std::to_string(judged)}}});
  if (judged < boxes)
    add_note({MessageId::note_box_not_judged, {{"count", std::to_string(boxes - judged)}, {"of", std::to_string(boxes)}}});
  // A box test that keeps none of the twins leaves nothing to judge here, and earns nothing, as a
  // stub does (docs/instructors.md, "Each stage graded on its own").
  if (judged == 0) {
    add_failure(MessageId::robust_failure_box_nothing_judged);
    return;
  }
  if (lost > 0) {
    add_hint(MessageId::robust_box_edge);
    add_failure({MessageId::robust_failure_box_edge,
                 {{"lost", gtest_text(lost)}, {"rays", gtest_text(judged)}, {"ray", ray_text(std::get<0>(touching[first]))},
                  {"box", box_text(std::get<2>(touching[first]))}}});
  }
}

// For information only (0 points), and last, so that a stage 03 that crashes or hangs costs
// nothing here: how many of the same rays your stage 03 intersect_ray_triangle lets through.
GRADED_TEST(kStage, Stage06Robustness, ForComparisonYourStage03Leaks, 0) {
  for (const NamedMesh& mesh : {icosphere(3, 1.0f, glm::vec3(0.1f, -0.2f, 0.3f)), grid_cube(8, 1.0f, glm::vec3(0.0f))}) {
    try {
      const std::uint64_t leaks = count_leaks(mesh.mesh, &intersect_ray_triangle, kLeakRays, 6).leaks;
      add_note({MessageId::note_stage03_leaks,
                {{"mesh", mesh.name}, {"leaks", std::to_string(leaks)}, {"rays", std::to_string(kLeakRays)}}});
    } catch (const NotImplemented&) {
      add_note(MessageId::note_stage03_not_written);
      return;
    }
  }
}

}  // namespace
}  // namespace raylab::grading
