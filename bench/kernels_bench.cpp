// raylab-bench-kernels: run time against error for every intersection kernel, in one table.
//
//   build/bin/raylab-bench-kernels [--output DIR] [--rays N] [--no-plot]
//
// For each kernel (ray-sphere: textbook quadratic, stable form = stage 02's reference;
// ray-triangle: Moller-Trumbore = stage 03's reference, Cramer's rule, watertight = bonus stage 06_robustness's
// reference; ray-box: plain slab test, Ize-conservative slab test = stage 04's reference):
//   ns/test      the fastest of 15 timed passes over 4096 ordinary inputs (what a renderer
//                sees), 64 times each, the kernels of a group taking turns, on one thread (a
//                call through a function pointer included), with the ratio to the fastest
//                kernel of the same group;
//   errors       relative error of t against long double on the ADVERSARIAL sets of
//                tests/stress (far/tiny and huge spheres, grazing rays, near-parallel rays,
//                slivers, large coordinates): max and 99.9th percentile, and wrong hit/miss
//                decisions per million where the answer is clear;
//   leaks        rays per million that slip through closed meshes at shared edges and vertices
//                (triangles), or boxes wrongly rejected per million boxes holding a hit (boxes).
// Writes DIR/kernels.csv and, unless --no-plot, runs tools/plot_kernels.py to draw
// DIR/kernels.png (needs /usr/bin/python3 with matplotlib). docs/accuracy.md shows a run.
#include "stress_kernels.h"

#include "raylab/stages/02_sphere.h"
#include "raylab/stages/03b_watertight.h"
#include "raylab/stages/04_box.h"
#include "raylab/testkit/oracles.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using namespace raylab;
using namespace raylab::stress;

struct Row {
  std::string group, algorithm, note;
  double ns_per_test = 0, ratio = 0;
  double max_error = 0, p999_error = 0, wrong_per_million = 0;
  double leaks_per_million = -1;  // -1: not measured for this group
};

// Time per call of `body(kernel, i)` for each kernel of a group: the fastest of 15 timed
// passes (after a warm-up; the minimum, because other processes only ever add time). The
// kernels take turns pass by pass, so a busy moment of the machine hits them alike. Each pass
// calls a kernel 64 times on the first min(count, 4096) inputs: a working set that stays in
// the cache, so that the figure is the kernel's arithmetic, not memory traffic.
template <typename Kernel, typename Body>
std::vector<double> nanoseconds_per_test(const std::vector<Kernel>& kernels, std::size_t count, Body body) {
  const std::size_t inputs = std::min<std::size_t>(count, 4096);
  constexpr int kRepeats = 64;
  std::vector<double> best(kernels.size(), 1e300);
  for (int pass = 0; pass < 16; ++pass) {
    for (std::size_t k = 0; k < kernels.size(); ++k) {
      const auto start = std::chrono::steady_clock::now();
      for (int repeat = 0; repeat < kRepeats; ++repeat)
        for (std::size_t i = 0; i < inputs; ++i) body(kernels[k], i);
      const auto stop = std::chrono::steady_clock::now();
      const double ns = std::chrono::duration<double, std::nano>(stop - start).count() / double(inputs * kRepeats);
      if (pass > 0) best[k] = std::min(best[k], ns);
    }
  }
  return best;
}

// ---- Spheres ----------------------------------------------------------------------------

using SphereKernel = std::optional<float> (*)(const Ray&, const glm::vec3&, float);

void sphere_rows(int rays, std::vector<Row>& rows) {
  const std::vector<SphereCase> timing = sphere_cases("ordinary", rays, 11);
  std::vector<SphereCase> adversarial;
  for (const char* set : {"far_tiny", "huge_near", "grazing"}) {
    const std::vector<SphereCase> cases = sphere_cases(set, rays / 3, 12);
    adversarial.insert(adversarial.end(), cases.begin(), cases.end());
  }
  const struct {
    const char* name;
    SphereKernel kernel;
    const char* note;
  } kernels[] = {{"sphere_textbook", &sphere_textbook, "b^2 - 4ac and (-b - sqrt) / 2a"},
                 {"sphere_stable", &intersect_ray_sphere, "stage 02 reference"}};
  const std::vector<double> times = nanoseconds_per_test(
      std::vector<SphereKernel>{kernels[0].kernel, kernels[1].kernel}, timing.size(), [&](SphereKernel kernel, std::size_t i) {
        benchmark::DoNotOptimize(kernel(timing[i].ray, timing[i].center, timing[i].radius));
      });
  int n = 0;
  for (const auto& k : kernels) {
    Row row{"sphere", k.name, k.note};
    row.ns_per_test = times[n++];
    ErrorStats stats;
    for (const SphereCase& c : adversarial) {
      long double margin = 0;
      const auto expected = testkit::exact_sphere_hit(c.ray, c.center, c.radius, &margin);
      const auto got = k.kernel(c.ray, c.center, c.radius);
      ++stats.inputs;
      if (got.has_value() != expected.has_value()) stats.wrong_decisions += margin > 1e-3;
      else if (got) stats.add(*got, *expected);
    }
    row.max_error = stats.max(), row.p999_error = stats.percentile(99.9);
    row.wrong_per_million = 1e6 * double(stats.wrong_decisions) / double(stats.inputs);
    rows.push_back(row);
  }
}

// ---- Triangles --------------------------------------------------------------------------

void triangle_rows(int rays, std::vector<Row>& rows) {
  const std::vector<TriangleCase> timing = triangle_cases("ordinary", rays, 21);
  std::vector<TriangleCase> adversarial;
  for (const char* set : {"near_parallel", "slivers", "large_coords"}) {
    const std::vector<TriangleCase> cases = triangle_cases(set, rays / 3, 22);
    adversarial.insert(adversarial.end(), cases.begin(), cases.end());
  }
  const std::vector<ClosedMesh> meshes = leak_test_meshes();
  const char* notes[] = {"stage 03 reference", "Sarrus determinants", "stage 06 reference"};
  std::vector<TriangleKernel> pointers;
  for (const NamedTriangleKernel& k : triangle_kernels()) pointers.push_back(k.kernel);
  const std::vector<double> times =
      nanoseconds_per_test(pointers, timing.size(), [&](TriangleKernel kernel, std::size_t i) {
        benchmark::DoNotOptimize(kernel(timing[i].ray, timing[i].p0, timing[i].p1, timing[i].p2));
      });
  int n = 0;
  for (const NamedTriangleKernel& k : triangle_kernels()) {
    Row row{"triangle", k.name, notes[n]};
    row.ns_per_test = times[n++];
    ErrorStats stats;
    for (const TriangleCase& c : adversarial) {
      ++stats.inputs;
      const auto got = k.kernel(c.ray, c.p0, c.p1, c.p2);
      if (got && !std::isfinite(got->t_hit)) {
        ++stats.non_finite;
        continue;
      }
      const TriangleReference expected = triangle_reference(c.ray, c.p0, c.p1, c.p2);
      if (expected.parallel || !(expected.t > 0)) continue;
      if ((got && expected.outside_clearly) || (!got && expected.inside_clearly)) ++stats.wrong_decisions;
      if (got && expected.inside_clearly) stats.add(got->t_hit, expected.t);
    }
    row.max_error = stats.max(), row.p999_error = stats.percentile(99.9);
    row.wrong_per_million = 1e6 * double(stats.wrong_decisions) / double(stats.inputs);
    std::uint64_t leaks = 0, leak_rays = 0;
    for (const ClosedMesh& mesh : meshes) {
      const LeakCount count = count_leaks(mesh, k.kernel, static_cast<std::uint64_t>(rays), 23);
      leaks += count.leaks, leak_rays += count.rays;
    }
    row.leaks_per_million = 1e6 * double(leaks) / double(leak_rays);
    rows.push_back(row);
  }
}

// ---- Boxes ------------------------------------------------------------------------------

using BoxKernel = std::optional<float> (*)(const Ray&, const glm::vec3&, const Bounds3&);

void box_rows(int rays, std::vector<Row>& rows) {
  // Timing: boxes around the ordinary triangles. Errors: t_enter on the boxes of the
  // adversarial triangles against long double; rejections: the boxes of the triangles that
  // the watertight test hits, for rays through the shared edges of the leak-test meshes.
  const std::vector<TriangleCase> timing = triangle_cases("ordinary", rays, 31);
  std::vector<Bounds3> timing_boxes;
  for (const TriangleCase& c : timing) timing_boxes.push_back(bounds_union(bounds_union(Bounds3(c.p0, c.p0), c.p1), c.p2));
  std::vector<glm::vec3> inverses;
  for (const TriangleCase& c : timing) inverses.push_back(ray_direction_inverse_of(c.ray));

  std::vector<TriangleCase> adversarial;
  for (const char* set : {"near_parallel", "slivers", "large_coords"}) {
    const std::vector<TriangleCase> cases = triangle_cases(set, rays / 3, 32);
    adversarial.insert(adversarial.end(), cases.begin(), cases.end());
  }
  const struct {
    const char* name;
    BoxKernel kernel;
    const char* note;
  } kernels[] = {{"box_plain_slab", &box_plain_slab, "no exit correction"},
                 {"box_ize_conservative", &intersect_ray_box, "stage 04 reference"}};
  const std::vector<ClosedMesh> meshes = leak_test_meshes();
  const std::vector<double> times = nanoseconds_per_test(
      std::vector<BoxKernel>{kernels[0].kernel, kernels[1].kernel}, timing.size(), [&](BoxKernel kernel, std::size_t i) {
        benchmark::DoNotOptimize(kernel(timing[i].ray, inverses[i], timing_boxes[i]));
      });
  int n = 0;
  for (const auto& k : kernels) {
    Row row{"box", k.name, k.note};
    row.ns_per_test = times[n++];
    ErrorStats stats;
    for (const TriangleCase& c : adversarial) {
      const Bounds3 bounds = bounds_union(bounds_union(Bounds3(c.p0, c.p0), c.p1), c.p2);
      // Exact entry distance in long double.
      long double enter = 0, exit = 1e300L;
      for (int axis = 0; axis < 3; ++axis) {
        const long double o = c.ray.origin[axis], d = c.ray.direction[axis];
        if (d == 0) {
          if (o < bounds.min[axis] || o > bounds.max[axis]) exit = -1;
          continue;
        }
        long double t0 = (bounds.min[axis] - o) / d, t1 = (bounds.max[axis] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0), exit = std::min(exit, t1);
      }
      ++stats.inputs;
      const auto got = k.kernel(c.ray, ray_direction_inverse_of(c.ray), bounds);
      const bool hit = enter <= exit;
      if (got.has_value() != hit) {
        // A box the exact ray misses by less than rounding may be accepted (conservative);
        // a box it meets must never be rejected.
        if (hit) ++stats.wrong_decisions;
      } else if (got && enter > 0) {
        stats.add(*got, enter);
      }
    }
    row.max_error = stats.max(), row.p999_error = stats.percentile(99.9);
    row.wrong_per_million = 1e6 * double(stats.wrong_decisions) / double(stats.inputs);
    // Boxes of triangles hit by the watertight test, rays through shared edges.
    std::uint64_t boxes_tested = 0, rejected = 0;
    for (const ClosedMesh& mesh : meshes) {
      Pcg32 random(33);
      auto corner = [&](std::size_t t, int j) { return mesh.positions[mesh.indices[3 * t + j]]; };
      for (int r = 0; r < rays / 4; ++r) {
        const std::size_t t = random.next_bounded(static_cast<std::uint32_t>(mesh.triangle_count()));
        const int j = random_integer(random, 0, 2);
        const glm::vec3 target = glm::clamp(glm::mix(corner(t, j), corner(t, (j + 1) % 3), random.uniform(0, 1)),
                                            glm::min(corner(t, j), corner(t, (j + 1) % 3)),
                                            glm::max(corner(t, j), corner(t, (j + 1) % 3)));
        Ray ray;
        ray.origin = mesh.inside + random.uniform(0.0f, 0.9f) * mesh.inside_radius * random_unit_vector(random);
        ray.direction = target - ray.origin;
        const Bounds3 bounds = bounds_union(bounds_union(Bounds3(corner(t, 0), corner(t, 0)), corner(t, 1)), corner(t, 2));
        ++boxes_tested;
        if (!k.kernel(ray, ray_direction_inverse_of(ray), bounds)) ++rejected;
      }
    }
    row.leaks_per_million = 1e6 * double(rejected) / double(boxes_tested);
    rows.push_back(row);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string output = RAYLAB_BENCH_DEFAULT_OUTPUT;
  int rays = 200000;
  bool plot = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--output" && i + 1 < argc) output = argv[++i];
    else if (arg == "--rays" && i + 1 < argc) rays = std::max(1000, std::atoi(argv[++i]));
    else if (arg == "--no-plot") plot = false;
    else {
      std::fprintf(stderr, "usage: raylab-bench-kernels [--output DIR] [--rays N] [--no-plot]\n");
      return 1;
    }
  }
  std::vector<Row> rows;
  std::printf("raylab-bench-kernels: %d rays per input set, one thread\n", rays);
  sphere_rows(rays, rows);
  triangle_rows(rays, rows);
  box_rows(rays, rows);
  for (Row& row : rows) {
    double fastest = 1e300;
    for (const Row& other : rows)
      if (other.group == row.group) fastest = std::min(fastest, other.ns_per_test);
    row.ratio = row.ns_per_test / fastest;
  }

  std::printf("\n%-22s %9s %7s %10s %10s %12s %14s  %s\n", "algorithm", "ns/test", "ratio", "max rel", "p99.9 rel",
              "wrong/1e6", "leaks/1e6", "note");
  for (const Row& row : rows) {
    char leaks[32] = "-";
    if (row.leaks_per_million >= 0) std::snprintf(leaks, sizeof leaks, "%.0f", row.leaks_per_million);
    std::printf("%-22s %9.2f %7.2f %10.2e %10.2e %12.0f %14s  %s\n", row.algorithm.c_str(), row.ns_per_test, row.ratio,
                row.max_error, row.p999_error, row.wrong_per_million, leaks, row.note.c_str());
  }
  std::printf("(leaks/1e6: triangles, rays slipping through closed meshes; boxes, boxes holding a hit that are rejected)\n");

  std::filesystem::create_directories(output);
  const std::string csv = output + "/kernels.csv";
  {
    std::ofstream out(csv);
    out << "group,algorithm,ns_per_test,ratio_to_fastest_in_group,max_relative_error,p999_relative_error,"
           "wrong_decisions_per_million,leaks_per_million,note\n";
    for (const Row& row : rows) {
      out << row.group << "," << row.algorithm << "," << row.ns_per_test << "," << row.ratio << "," << row.max_error << ","
          << row.p999_error << "," << row.wrong_per_million << ",";
      if (row.leaks_per_million >= 0) out << row.leaks_per_million;
      out << ",\"" << row.note << "\"\n";  // quoted: notes may hold commas
    }
    if (!out) {
      std::fprintf(stderr, "raylab-bench-kernels: cannot write %s\n", csv.c_str());
      return 1;
    }
  }
  std::printf("wrote %s\n", csv.c_str());
  if (plot) {
    const std::string png = output + "/kernels.png";
    const std::string command = "/usr/bin/python3 \"" RAYLAB_SOURCE_DIR "/tools/plot_kernels.py\" \"" + csv + "\" \"" + png + "\"";
    if (std::system(command.c_str()) == 0) std::printf("wrote %s\n", png.c_str());
    else std::printf("no plot (needs /usr/bin/python3 with matplotlib): %s\n", command.c_str());
  }
  return 0;
}
