// Autograder suite for the bonus stage 06_robustness (18 points): your kernels on inputs
// chosen to break float arithmetic. Handouts: docs/accuracy.md, docs/02_sphere.md (section 3)
// and docs/03b_watertight.md.
//
//   - intersect_ray_sphere (stage 02) on small spheres far away and huge spheres seen from
//     close by, against the EXACT answer for the float inputs (long double, checked in by the
//     regenerate tool): the textbook quadratic loses digits to catastrophic cancellation;
//   - intersect_ray_triangle_watertight (stage 03b): the same answers as stage 03, zero rays
//     slipping through closed meshes at their shared edges and vertices, and no NaN from
//     degenerate triangles or rays parallel to them. Your stage 03 (Moller-Trumbore) leak count
//     is shown as a note, for comparison (0 points).
#include "grading.h"
#include "support.h"

#include "raylab/error.h"
#include "raylab/mesh_generator.h"
#include "raylab/stages/02_sphere.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/stages/03b_watertight.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "06_robustness";
const bool kRegistered = register_stage(kStage, [] {
  (void)intersect_ray_triangle_watertight(Ray{}, glm::vec3(-1, -1, -2), glm::vec3(1, -1, -2), glm::vec3(0, 1, -2));
});

// The reference's error on these cases is below 3e-6; the textbook quadratic's reaches 1e-3.
constexpr double kSphereRelativeTolerance = 1e-5;

const char* const kCancellationHint =
    "loses digits to catastrophic cancellation: b^2 - 4ac subtracts two nearly equal numbers when the sphere is small "
    "and far, and -b - sqrt(discriminant) does when the origin is close to a large sphere. Compute the discriminant "
    "from the distance between the centre and the ray's line, and the roots as q = -(b + sign(b) sqrt(disc)) / 2, "
    "t0 = q / a, t1 = c / q (docs/02_sphere.md, section 3)";

Ray make_ray(glm::vec3 origin, glm::vec3 direction) {
  Ray ray;
  ray.origin = origin;
  ray.direction = direction;
  return ray;
}

void check_sphere_cases(const std::string& kind) {
  const nlohmann::json data = load_reference_cases("06_robustness");
  int checked = 0, failures = 0;
  double worst = 0.0;
  for (const nlohmann::json& c : data.at("cases")) {
    if (c.at("kind") != kind) continue;
    ++checked;
    const Ray ray = make_ray(vec3_from_json(c.at("origin")), vec3_from_json(c.at("direction")));
    const glm::vec3 center = vec3_from_json(c.at("center"));
    const float radius = c.at("radius").get<float>();
    const bool expected_hit = !c.at("t_exact").is_null();
    const double expected_t = expected_hit ? c.at("t_exact").get<double>() : 0.0;
    const std::optional<float> got = intersect_ray_sphere(ray, center, radius);
    bool ok = got.has_value() == expected_hit;
    if (ok && got) {
      const double error = std::fabs(double(*got) - expected_t) / std::fabs(expected_t);
      worst = std::max(worst, std::isfinite(error) ? error : 1e30);
      ok = error <= kSphereRelativeTolerance;
    }
    if (ok) continue;
    if (++failures <= 3) {
      std::ostringstream got_text;
      if (got) got_text << "t = " << *got; else got_text << "no hit";
      ADD_FAILURE() << "case " << c.at("id") << " (" << kind << "): ray " << ray << ", sphere " << center << " radius "
                    << radius << "\n  expected " << (expected_hit ? "t = " + std::to_string(expected_t) : "no hit")
                    << " (exact, relative tolerance " << kSphereRelativeTolerance << ")\n  got      " << got_text.str();
    }
  }
  if (failures > 0) add_hint(kCancellationHint);
  char worst_text[32];
  std::snprintf(worst_text, sizeof worst_text, "%.2e", worst);
  add_note(kind + ": largest relative error of t " + worst_text + " over " + std::to_string(checked) + " spheres");
  EXPECT_EQ(failures, 0) << failures << " of " << checked << " " << kind << " spheres wrong (seed " << data.at("seed") << ")";
}

GRADED_TEST(kStage, Stage06Robustness, SmallSpheresFarAway, 4) { check_sphere_cases("far_tiny"); }

GRADED_TEST(kStage, Stage06Robustness, HugeSpheresSeenFromNearby, 3) { check_sphere_cases("huge_near"); }

// ---- Watertight triangles ---------------------------------------------------------------

bool close(float got, float expected) { return std::fabs(got - expected) <= 1e-4f * std::max(1.0f, std::fabs(expected)); }

GRADED_TEST(kStage, Stage06Robustness, WatertightMatchesStage03Answers, 3) {
  // The same contract as stage 03: the same hits, t and barycentrics on stage 03's cases.
  const nlohmann::json data = load_reference_cases("03_triangle");
  int failures = 0;
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
    if (got && expected && close(got->barycentric_b1, c["hit"].at(2).get<float>()) &&
        close(got->barycentric_b2, c["hit"].at(1).get<float>()))
      add_hint("barycentrics swapped: b1 = v / det is p1's weight and b2 = w / det is p2's (docs/03b_watertight.md, section 2)");
    else if (got && expected && close(got->t_hit, c["hit"].at(0).get<float>()))
      add_hint("the barycentrics are wrong: u is p0's weight (edge p1-p2), v is p1's, w is p2's; divide each by det");
    else if (!got && expected)
      add_hint("misses triangles that stage 03 hits: check the sign test (u, v, w all >= 0 or all <= 0) and det != 0");
    else if (got && !expected)
      add_hint("reports hits that stage 03 rejects: check the sign test and t_min < t < t_max");
    if (++failures <= 3) {
      std::ostringstream got_text;
      if (got) got_text << *got; else got_text << "no hit";
      ADD_FAILURE() << "case " << c.at("id") << ": ray " << ray << ", triangle " << p0 << " " << p1 << " " << p2
                    << "\n  expected " << (expected ? c.at("hit").dump() : "no hit") << " (t, b1, b2)\n  got      "
                    << got_text.str();
    }
  }
  EXPECT_EQ(failures, 0) << failures << " of " << data.at("cases").size() << " stage 03 cases differ";
}

// A closed mesh: every edge is shared by exactly two triangles.
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
  glm::vec3 center{0.0f};
  float inner_radius = 0.0f;  // a ball around center inside the mesh
};

Mesh closed(TriangleMesh generated, const std::string& description, glm::vec3 center, float inner_radius) {
  return Mesh{description + " of " + std::to_string(generated.triangle_count()) + " triangles",
              std::move(generated.positions), std::move(generated.indices), center, inner_radius};
}

Mesh icosphere(int levels, float radius, glm::vec3 center) {
  return closed(make_icosphere(levels, radius, center), "a sphere", center, 0.5f * radius);
}

Mesh grid_cube(int n, float half, glm::vec3 center) {
  return closed(make_grid_cube(n, half, center), "a cube", center, 0.5f * half);
}

using TriangleTest = std::optional<TriangleHit> (*)(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&);

// Rays from inside the mesh aimed at points on its edges (half) and exactly at its vertices
// (half): each must hit some triangle. Returns the rays that hit none; the first is kept.
int count_leaks(const Mesh& mesh, TriangleTest test, int rays, std::uint32_t seed, Ray* first_leak) {
  std::vector<std::vector<std::uint32_t>> around(mesh.positions.size());
  const auto triangles = static_cast<std::uint32_t>(mesh.indices.size() / 3);
  for (std::uint32_t t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k) around[mesh.indices[3 * t + k]].push_back(t);
  auto hits = [&](const Ray& ray, std::uint32_t t) {
    return test(ray, mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                mesh.positions[mesh.indices[3 * t + 2]]).has_value();
  };
  Pcg32 random(seed, testkit::stream_of("leak rays"));
  int leaks = 0;
  for (int r = 0; r < rays; ++r) {
    const auto t = static_cast<std::uint32_t>(testkit::random_integer(random, 0, static_cast<int>(triangles) - 1));
    const int k = testkit::random_integer(random, 0, 2);
    const std::uint32_t a = mesh.indices[3 * t + k], b = mesh.indices[3 * t + (k + 1) % 3];
    const glm::vec3 target = r % 2 == 0 ? glm::mix(mesh.positions[a], mesh.positions[b], random.uniform(0, 1)) : mesh.positions[a];
    glm::vec3 offset = testkit::random_vec3(random, -1, 1);
    if (glm::length(offset) > 1.0f) offset /= glm::length(offset) * 1.01f;
    Ray ray = make_ray(mesh.center + 0.9f * mesh.inner_radius * offset, glm::vec3(0.0f));
    ray.direction = target - ray.origin;
    bool hit = false;
    for (std::uint32_t u : around[a]) hit = hit || hits(ray, u);
    for (std::uint32_t u : around[b]) hit = hit || hits(ray, u);
    for (std::uint32_t u = 0; !hit && u < triangles; ++u) hit = hits(ray, u);
    if (!hit && ++leaks == 1 && first_leak) *first_leak = ray;
  }
  return leaks;
}

constexpr int kLeakRays = 100000;

GRADED_TEST(kStage, Stage06Robustness, NoRayLeaksThroughClosedMeshes, 6) {
  constexpr int kRays = kLeakRays;
  const Mesh meshes[] = {icosphere(3, 1.0f, glm::vec3(0.1f, -0.2f, 0.3f)), grid_cube(8, 1.0f, glm::vec3(0.0f))};
  for (const Mesh& mesh : meshes) {
    Ray first_leak;
    const int leaks = count_leaks(mesh, &intersect_ray_triangle_watertight, kRays, 6, &first_leak);
    add_note("watertight, " + mesh.name + ": " + std::to_string(leaks) + " of " + std::to_string(kRays) +
             " rays through edges and vertices leaked");
    if (leaks > 0) {
      add_hint("rays slip between triangles at shared edges: compute each corner's sheared x, y from that corner alone "
               "(p - origin, then the shear), test all three edge functions with the same formula, count 0 as inside, "
               "and retry in double when one is exactly 0 (docs/03b_watertight.md, section 3)");
      ADD_FAILURE() << mesh.name << ": " << leaks << " of " << kRays
                    << " rays from inside through its edges and vertices hit no triangle; the first: " << first_leak;
    }
  }
}

GRADED_TEST(kStage, Stage06Robustness, DegenerateAndParallelInputsGiveNoNaN, 2) {
  const glm::vec3 p0(0, 0, -2), p1(1, 0, -2), p2(0, 1, -2);
  struct Input {
    const char* what;
    Ray ray;
    glm::vec3 a, b, c;
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
      {"infinite corner", ray_of({0.2f, 0.2f, 0}, {0, 0, -1}), p0, glm::vec3(kInfinity, 0, -2), p2},
      {"NaN corner", ray_of({0.2f, 0.2f, 0}, {0, 0, -1}), p0, p1, glm::vec3(std::nanf(""), 1, -2)},
  };
  for (const Input& input : inputs) {
    const std::optional<TriangleHit> got = intersect_ray_triangle_watertight(input.ray, input.a, input.b, input.c);
    if (!got) continue;
    const bool finite = std::isfinite(got->t_hit) && std::isfinite(got->barycentric_b1) && std::isfinite(got->barycentric_b2);
    if (finite && got->t_hit > input.ray.t_min) continue;  // a finite hit on a degenerate input is acceptable
    add_hint("NaN or infinity from a degenerate input: write every test so that NaN rejects (if (!(det != 0)) ...), "
             "reject det == 0 and a zero direction (docs/03b_watertight.md, section 3)");
    ADD_FAILURE() << input.what << ": ray " << input.ray << ", triangle " << input.a << " " << input.b << " " << input.c
                  << "\n  expected no hit (or a finite one)\n  got      " << *got;
  }
}

// For information only (0 points), and last, so that a stage 03 that crashes or hangs costs
// nothing here: how many of the same rays your stage 03 intersect_ray_triangle lets through.
GRADED_TEST(kStage, Stage06Robustness, ForComparisonYourStage03Leaks, 0) {
  for (const Mesh& mesh : {icosphere(3, 1.0f, glm::vec3(0.1f, -0.2f, 0.3f)), grid_cube(8, 1.0f, glm::vec3(0.0f))}) {
    try {
      const int leaks = count_leaks(mesh, &intersect_ray_triangle, kLeakRays, 6, nullptr);
      add_note("for comparison, your stage 03 intersect_ray_triangle (Moller-Trumbore), " + mesh.name + ": " +
               std::to_string(leaks) + " of " + std::to_string(kLeakRays) + " rays leaked");
    } catch (const NotImplemented&) {
      add_note("stage 03 is not written yet: no comparison with Moller-Trumbore");
      return;
    }
  }
}

}  // namespace
}  // namespace raylab::grading
