// The stress suite's tools, shared with bench/kernels_bench.cpp: baseline kernels that the
// reference stages are compared with (the textbook sphere quadratic, Cramer's rule, a plain
// slab test, fixed-epsilon ray offsets), high-precision references (long double; the sphere's
// is the test kit's, raylab/testkit/oracles.h), closed test meshes and the leak count (the
// test kit's, raylab/testkit/leaks.h), adversarial input sets, and error statistics.
//
// The baselines are (partly) valid stage solutions, so they live only here and in bench/,
// which the student release leaves out (tools/make-release), never in framework/ or
// assignments/.
#pragma once

#include "raylab/bounds.h"
#include "raylab/ray.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/testkit/leaks.h"
#include "raylab/testkit/random_values.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace raylab::stress {

// ---- Error statistics -------------------------------------------------------------------

// Relative errors |t - t_reference| / |t_reference| of one kernel on one input set, plus the
// decisions it got wrong (hit where the reference misses, or the other way round).
struct ErrorStats {
  std::vector<double> relative_errors;
  std::uint64_t inputs = 0;
  std::uint64_t wrong_decisions = 0;
  std::uint64_t non_finite = 0;  // hits with a NaN or infinite t or barycentric

  void add(double t, long double t_reference);
  double max() const;
  double percentile(double p) const;  // p in [0, 100]; 0 when there are no errors
  double median() const { return percentile(50.0); }
};

// "max 1.2e-07  p99.9 8.9e-08  median 2.1e-08  wrong 0/100000" for the report.
std::string describe(const ErrorStats& stats);

// ---- Deterministic random numbers: the kit's one generator -----------------------------
// Pcg32 (raylab/random.h) with raylab/testkit/random_values.h's random_unit_vector,
// random_log_uniform, random_integer; each case set draws from its own stream.
using testkit::random_integer;
using testkit::random_log_uniform;
using testkit::random_unit_vector;

// ---- Ray-sphere -------------------------------------------------------------------------

// The textbook quadratic: discriminant b^2 - 4ac, roots (-b -+ sqrt(disc)) / 2a. Same
// interval rules as the stage function.
std::optional<float> sphere_textbook(const Ray& ray, const glm::vec3& center, float radius);

// The exact answer for the float inputs is raylab/testkit/oracles.h's exact_sphere_hit.

struct SphereCase {
  Ray ray;
  glm::vec3 center;
  float radius;
};

// Adversarial sets, each `count` cases from `seed`:
//   far_tiny      spheres 100 to 100,000 from the origin, radius 1e-4 to 1e-2 of the distance
//   huge_near     spheres of radius 1e3 to 1e6 seen from 1e-4 to 1e-1 of the radius above them
//   grazing       rays passing 0.9 to 0.999999 of the radius from the centre
//   on_surface    origins on the surface (rounded to float), half going in, half out
//   ordinary      spheres of radius 0.1 to 5 within 20 of the origin (the autograder's kind)
std::vector<SphereCase> sphere_cases(const std::string& set, int count, std::uint64_t seed);
const std::vector<std::string>& sphere_case_sets();

// ---- Ray-triangle -----------------------------------------------------------------------

// Cramer's rule as it is usually first written: the four 3x3 determinants of
// [-d, e1, e2 | s], each expanded by Sarrus' rule. Same contract as the stage function.
std::optional<TriangleHit> triangle_cramer(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                           const glm::vec3& p2);

// The exact plane intersection in long double (no inside test): t and barycentrics, and
// whether the point is inside the triangle by more than `margin` in barycentric units
// (inside_clearly) or outside by more than it (outside_clearly).
struct TriangleReference {
  bool parallel = true;  // the ray is parallel to the plane, or the triangle is degenerate
  long double t = 0, b1 = 0, b2 = 0;
  bool inside_clearly = false, outside_clearly = false;
};
TriangleReference triangle_reference(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                     const glm::vec3& p2, long double margin = 1e-4L);

using TriangleKernel = testkit::TriangleFunction;
struct NamedTriangleKernel {
  const char* name;
  TriangleKernel kernel;
};
// Moller-Trumbore (stage 03's reference), Cramer's rule (baseline), watertight (stage 03b's
// reference).
const std::vector<NamedTriangleKernel>& triangle_kernels();

struct TriangleCase {
  Ray ray;
  glm::vec3 p0, p1, p2;
};
// Adversarial sets:
//   ordinary       triangles of size ~1 near the origin, rays from up to 10 away
//   near_parallel  rays at 1e-6 to 1e-2 radians from the triangle's plane
//   slivers        triangles 1e3 to 1e6 times longer than wide
//   large_coords   ordinary triangles and rays moved 1e4 to 1e6 from the origin
//   degenerate     zero-area triangles (a repeated corner, or three points on a line)
std::vector<TriangleCase> triangle_cases(const std::string& set, int count, std::uint64_t seed);
const std::vector<std::string>& triangle_case_sets();

// ---- Closed meshes and leaks ------------------------------------------------------------
// The closed meshes and the leak count are the test kit's (raylab/testkit/leaks.h), shared
// with the autograder's stage 06_robustness.

using testkit::ClosedMesh;
using testkit::LeakCount;

// An icosahedron subdivided `levels` times, on a sphere (20 * 4^levels triangles).
ClosedMesh make_icosphere(int levels, float radius, const glm::vec3& center);
// A cube whose faces are n x n grids of square pairs (12 n^2 triangles, coplanar neighbours).
ClosedMesh make_grid_cube(int n, float half_size, const glm::vec3& center);
// A double cone (bipyramid) of `segments` very thin triangles per half around its axis.
ClosedMesh make_sliver_bipyramid(int segments, float radius, float height, const glm::vec3& center);
// The meshes the leak tests use: icosphere, grid cube, the grid cube far from the origin,
// sliver bipyramid.
std::vector<ClosedMesh> leak_test_meshes();

// testkit::count_leaks with `kernel` in this process, `rays` rays from Pcg32(seed).
LeakCount count_leaks(const ClosedMesh& mesh, TriangleKernel kernel, std::uint64_t rays,
                      std::uint64_t seed);

// ---- Ray-box ----------------------------------------------------------------------------

// The slab test without Ize's correction of the exit distance (otherwise as the stage's
// reference): the rounding of (slab - origin) * inverse may put the exit a hair before the
// entry for a ray through a box's edge.
std::optional<float> box_plain_slab(const Ray& ray, const glm::vec3& inverse, const Bounds3& box);

// ---- Environment ------------------------------------------------------------------------

// RAYLAB_STRESS_FULL=1 in the environment: the larger sweeps.
bool full_sweep();

}  // namespace raylab::stress
