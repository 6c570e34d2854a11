// raylab-bench-bvh: how fast are the reference BVHs (stage 05_bvh), and how far from Embree?
//
//   build-bvh/bin/raylab-bench-bvh [--triangles N] [--threads T] [Google Benchmark flags]
//
// Meshes: the Stanford bunny (scenes/bunny.obj, 3674 triangles) and a displaced sphere of
// about N triangles (default 1,000,000) made by make_displaced_sphere: no big files.
// Accelerators: brute force (bunny only: every ray tests every triangle), the reference
// median-split BVH, the reference binned-SAH BVH, the SAH tree collapsed into a 4-wide one
// (stage 05c; "sah-wide": its leaves' triangles tested four at a time; "sah-wide-serial": one
// after another), the same tree 8 wide with AVX2 box tests ("sah-wide8", solutions/05c_wide_bvh/
// wide8.h: what raylab-reference traces; not on a CPU without AVX2), and Embree (3 or 4) when
// CMake found it.
// Rays: "primary" (a 512 x 384 camera framing the mesh) and "random" (origins spread over
// 1.5 times the mesh's box, directions uniform on the sphere), each traced as closest hit
// and as any hit (t_max = infinity). Each timed iteration traces the whole set on one thread
// (with --threads T > 1, a second series spreads the rays over T threads in chunks).
//
// After Google Benchmark's own table the program prints a summary: build times, and each
// traversal as Mrays/s and as a ratio to Embree's time in the same run (2.0 = twice Embree's
// time), with the exact work per ray (nodes visited, triangles tested: identical on every
// machine) and the SAH cost of each tree. Before timing, every BVH's closest hits are checked
// ray by ray against an oracle (brute force on the bunny, Embree or the other BVH otherwise).
#include "raylab/bounds.h"
#include "raylab/camera.h"
#include "raylab/integrator.h"
#include "raylab/mesh_generator.h"
#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/stages/01_camera_rays.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/bvh_tools.h"
#include "raylab/stages/05_bvh.h"
#include "raylab/stages/05c_wide_bvh.h"

#include "../solutions/05c_wide_bvh/fast_tree.h"  // "sah-wide8", and the renderer's tree
#include "raylab/testkit/random_values.h"
#include "raylab/testkit/triangles.h"

#include <benchmark/benchmark.h>

#if defined(RAYLAB_HAVE_EMBREE) && RAYLAB_HAVE_EMBREE >= 4
#include <embree4/rtcore.h>
#elif defined(RAYLAB_HAVE_EMBREE)
#include <embree3/rtcore.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using namespace raylab;

constexpr int kLeafSize = 4;                       // as the renderer (SceneGeometry)
constexpr int kPrimaryWidth = 512, kPrimaryHeight = 384;
constexpr std::size_t kRandomRayCount = kPrimaryWidth * kPrimaryHeight;
constexpr std::size_t kBruteForceStride = 16;      // brute force traces every 16th ray

// ---- Deterministic inputs ---------------------------------------------------------------

struct TestMesh {
  std::string name;
  std::vector<glm::vec3> corners;  // 3 per triangle
  Bounds3 bounds;
  bool brute_force = false;        // small enough to trace with brute force
  std::size_t triangle_count() const { return corners.size() / 3; }
};

TestMesh make_test_mesh(const std::string& name, const TriangleMesh& mesh, bool brute_force) {
  TestMesh test{name, {}, {}, brute_force};
  test.corners.reserve(mesh.indices.size());
  for (std::uint32_t index : mesh.indices) {
    test.corners.push_back(mesh.positions[index]);
    test.bounds.extend(mesh.positions[index]);
  }
  return test;
}

struct RaySet {
  std::string name;
  std::vector<Ray> rays;
};

RaySet primary_rays(const Bounds3& bounds) {
  Camera camera;
  const glm::vec3 center = bounds.centroid();
  const float radius = 0.5f * glm::length(bounds.extent());
  camera.look_at = center;
  camera.position = center + 2.4f * radius * glm::normalize(glm::vec3(-0.45f, 0.35f, 1.0f));
  camera.fov_y_degrees = 40.0f;
  camera.width = kPrimaryWidth;
  camera.height = kPrimaryHeight;
  RaySet set{"primary", {}};
  set.rays.reserve(static_cast<std::size_t>(camera.width) * camera.height);
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) set.rays.push_back(generate_camera_ray(camera, x, y));
  return set;
}

RaySet random_rays(const Bounds3& bounds, std::uint64_t seed) {
  RaySet set{"random", {}};
  set.rays.reserve(kRandomRayCount);
  const glm::vec3 center = bounds.centroid(), half = 0.75f * bounds.extent();
  Pcg32 random(seed);  // the kit's one generator: the same rays on every machine
  while (set.rays.size() < kRandomRayCount) {
    Ray ray;
    ray.origin = center + half * testkit::random_vec3(random, -1.0f, 1.0f);
    ray.direction = testkit::random_unit_vector(random);
    set.rays.push_back(ray);
  }
  return set;
}

// ---- The reference BVHs, with triangles in leaf order (as the renderer stores them) ----

struct TriangleContext {
  const glm::vec3* corners;
  TriangleHit best;  // the renderer keeps the barycentrics of the best hit: so do we
};

std::optional<float> test_triangle(void* context, const Ray& ray, std::uint32_t triangle) {
  auto& ctx = *static_cast<TriangleContext*>(context);
  const glm::vec3* p = ctx.corners + 3 * static_cast<std::size_t>(triangle);
  const std::optional<TriangleHit> hit = intersect_ray_triangle(ray, p[0], p[1], p[2]);
  if (!hit) return std::nullopt;
  ctx.best = *hit;
  return hit->t_hit;
}

std::vector<Bounds3> triangle_boxes(const TestMesh& mesh) {
  std::vector<Bounds3> boxes(mesh.triangle_count());
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (int k = 0; k < 3; ++k) boxes[i].extend(mesh.corners[3 * i + k]);
  return boxes;
}

#if RAYLAB_AVX2_COMPILES
using EightWide = reference::Bvh8;
#else
struct EightWide {};  // (never built)
#endif

struct ReferenceBvh {
  std::string name;  // "median" or "sah"; "median-calls", "sah-calls": the same tree, tested by calls
  Bvh bvh;
  std::vector<glm::vec3> corners;  // in leaf order; bvh.primitive_order is the identity
  // The same triangles for the reference traversal's inlined test (reference::LeafTriangles),
  // as the reference's fastest tree holds them; empty: a call of test_triangle per triangle, as
  // a student's traversal and every grader run it.
  std::vector<reference::TriangleEdges> edges;
  // "sah-wide": bvh collapsed into a 4-wide tree (stage 05c), traversed by intersect_bvh4.
  std::optional<Bvh4> wide;
  // "sah-wide8": bvh as the reference's 8-wide tree (solutions/05c_wide_bvh/wide8.h), its
  // triangles as columns tested four at a time; what raylab-reference traces.
  std::shared_ptr<const EightWide> wide8;
  // "sah-wide": the triangles also as columns (reference::LeafTriangles::columns), tested four
  // at a time, as the reference's fastest tree holds them; "sah-wide-serial": without, one
  // after another.
  std::vector<float> columns;
  bool tested_by_calls() const { return edges.empty(); }
};

ReferenceBvh build_reference(const TestMesh& mesh, bool sah) {
  ReferenceBvh result{sah ? "sah" : "median", {}, {}, {}, std::nullopt, nullptr, {}};
  const std::vector<Bounds3> boxes = triangle_boxes(mesh);
  result.bvh = sah ? build_bvh_sah(boxes, kLeafSize) : build_bvh(boxes, kLeafSize);
  result.corners.reserve(mesh.corners.size());
  for (std::uint32_t& primitive : result.bvh.primitive_order) {
    for (int k = 0; k < 3; ++k) result.corners.push_back(mesh.corners[3 * std::size_t(primitive) + k]);
    primitive = static_cast<std::uint32_t>(&primitive - result.bvh.primitive_order.data());
  }
  for (std::size_t i = 0; i < result.corners.size(); i += 3)
    result.edges.push_back(reference::TriangleEdges::of(result.corners[i], result.corners[i + 1], result.corners[i + 2]));
  return result;
}

// The same tree, its triangles tested by a call each (the "-calls" rows).
ReferenceBvh tested_by_calls(const ReferenceBvh& tree) {
  ReferenceBvh copy = tree;
  copy.name += "-calls";
  copy.edges.clear();
  return copy;
}

// The same tree collapsed into a 4-wide one (the "-wide" rows), its triangles tested inlined,
// four at a time or (the "-wide-serial" rows) one after another.
ReferenceBvh collapsed(const ReferenceBvh& tree, bool four_at_a_time) {
  ReferenceBvh copy = tree;
  copy.name += four_at_a_time ? "-wide" : "-wide-serial";
  copy.wide = collapse_bvh4(tree.bvh);
  if (four_at_a_time) copy.columns = reference::triangle_columns(copy.edges.data(), copy.wide->primitive_order);
  return copy;
}

// The same tree as the reference's 8-wide one (the "-wide8" rows); nullopt on a CPU without AVX2.
std::optional<ReferenceBvh> collapsed8(const ReferenceBvh& tree) {
#if RAYLAB_AVX2_COMPILES
  if (!reference::eight_wide_tree_runs_here() || tree.bvh.nodes.empty()) return std::nullopt;
  ReferenceBvh copy = tree;
  copy.name += "-wide8";
  copy.wide8 = std::make_shared<const EightWide>(reference::collapse_bvh8(tree.bvh));
  copy.columns = reference::triangle_columns(copy.edges.data(), tree.bvh.primitive_order);
  return copy;
#else
  (void)tree;
  return std::nullopt;
#endif
}

// Traces rays[begin, end) (every `stride`-th); writes t (infinity for a miss) when t_out.
void trace_reference(const ReferenceBvh& tree, const std::vector<Ray>& rays, std::size_t begin,
                     std::size_t end, bool any_hit, float* t_out, BvhTraversalStats& stats) {
  TriangleContext context{tree.corners.data(), {}};
  PrimitiveIntersector intersector{&test_triangle, &context};
  reference::LeafTriangles leaves;
  leaves.triangles = tree.edges.data();
  if (!tree.columns.empty()) leaves.columns = reference::TriangleColumns::of(tree.columns);
  const bool calls = tree.tested_by_calls();
  for (std::size_t i = begin; i < end; ++i) {
    // Not const: DoNotOptimize(const T&) is deprecated since Google Benchmark 1.8.
    std::optional<BvhHit> hit;
#if RAYLAB_AVX2_COMPILES
    if (tree.wide8)
      hit = calls ? reference::intersect_bvh8(*tree.wide8, rays[i], intersector, any_hit, stats)
                  : reference::intersect_bvh8_inlined(*tree.wide8, rays[i], leaves, any_hit, stats);
    else
#endif
    if (tree.wide)
      hit = calls ? intersect_bvh4(*tree.wide, rays[i], intersector, any_hit, stats)
                  : reference::intersect_bvh4_inlined(*tree.wide, rays[i], leaves, any_hit, stats);
    else
      hit = calls ? intersect_bvh(tree.bvh, rays[i], intersector, any_hit, stats)
                  : reference::intersect_bvh_inlined(tree.bvh, rays[i], leaves, any_hit, stats);
    if (t_out) t_out[i] = hit ? hit->t_hit : kInfinity;
    benchmark::DoNotOptimize(hit);
  }
}

void trace_brute_force(const TestMesh& mesh, const std::vector<Ray>& rays, bool any_hit,
                       float* t_out, BvhTraversalStats& stats) {
  TriangleContext context{mesh.corners.data(), {}};
  const auto count = static_cast<std::uint32_t>(mesh.triangle_count());
  for (std::size_t i = 0; i < rays.size(); i += kBruteForceStride) {
    const std::optional<BvhHit> best =
        testkit::brute_force_hit(count, rays[i], any_hit, [&](const Ray& search, std::uint32_t triangle) {
          ++stats.primitives_tested;
          return test_triangle(&context, search, triangle);
        });
    float t_best = best ? best->t_hit : kInfinity;  // not const: see trace_reference
    if (t_out) t_out[i] = t_best;
    benchmark::DoNotOptimize(t_best);
  }
}

// ---- Embree 3 or 4 ------------------------------------------------------------------------

#ifdef RAYLAB_HAVE_EMBREE
struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  EmbreeScene() = default;
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  ~EmbreeScene() {
    if (scene) rtcReleaseScene(scene);
  }
};

RTCDevice embree_device(int threads) {
  const std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  RTCDevice device = rtcNewDevice(config.c_str());
  if (!device) {
    std::fprintf(stderr, "raylab-bench-bvh: rtcNewDevice failed (error %d)\n", rtcGetDeviceError(nullptr));
    std::exit(1);
  }
  return device;
}

// Default build quality (medium), as an application would start; a static scene.
void build_embree(EmbreeScene& out, RTCDevice device, const TestMesh& mesh) {
  if (out.scene) rtcReleaseScene(out.scene);
  out.device = device;
  out.scene = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const std::size_t triangles = mesh.triangle_count();
  // Embree's own buffers are aligned and padded as it wants; one vertex per corner.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.corners.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles));
  std::memcpy(vertices, mesh.corners.data(), mesh.corners.size() * sizeof(glm::vec3));
  for (std::size_t i = 0; i < 3 * triangles; ++i) indices[i] = static_cast<unsigned>(i);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(out.scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(out.scene);
}

void trace_embree(const EmbreeScene& embree, const std::vector<Ray>& rays, std::size_t begin,
                  std::size_t end, bool any_hit, float* t_out) {
#if RAYLAB_HAVE_EMBREE < 4
  RTCIntersectContext context;  // Embree 3 only; Embree 4's default arguments do the same
  rtcInitIntersectContext(&context);
#endif
  for (std::size_t i = begin; i < end; ++i) {
    const Ray& ray = rays[i];
    RTCRayHit query;
    query.ray.org_x = ray.origin.x;
    query.ray.org_y = ray.origin.y;
    query.ray.org_z = ray.origin.z;
    query.ray.dir_x = ray.direction.x;
    query.ray.dir_y = ray.direction.y;
    query.ray.dir_z = ray.direction.z;
    query.ray.tnear = ray.t_min;
    query.ray.tfar = ray.t_max;
    query.ray.time = 0.0f;
    query.ray.mask = 0xffffffffu;
    query.ray.id = 0;
    query.ray.flags = 0;
    float t = kInfinity;
    if (any_hit) {
#if RAYLAB_HAVE_EMBREE >= 4
      rtcOccluded1(embree.scene, &query.ray);
#else
      rtcOccluded1(embree.scene, &context, &query.ray);
#endif
      if (query.ray.tfar < 0.0f) t = 0.0f;  // occluded: Embree sets tfar to -infinity
    } else {
      query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
#if RAYLAB_HAVE_EMBREE >= 4
      rtcIntersect1(embree.scene, &query);
#else
      rtcIntersect1(embree.scene, &context, &query);
#endif
      if (query.hit.geomID != RTC_INVALID_GEOMETRY_ID) t = query.ray.tfar;
    }
    if (t_out) t_out[i] = t;
    benchmark::DoNotOptimize(t);
  }
}
#endif

// ---- Running on several threads: contiguous chunks of the ray set ----------------------

// Threads take blocks of 1024 rays in turn (block b to thread b mod T): a camera's rows of
// sky and of geometry are spread evenly, and each block is still coherent.
template <typename TraceChunk>
void parallel_for_chunks(std::size_t count, int threads, TraceChunk&& trace_chunk) {
  if (threads <= 1) {
    trace_chunk(std::size_t{0}, count);
    return;
  }
  constexpr std::size_t kBlock = 1024;
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t)
    workers.emplace_back([&trace_chunk, count, threads, t] {
      for (std::size_t begin = kBlock * static_cast<std::size_t>(t); begin < count;
           begin += kBlock * static_cast<std::size_t>(threads))
        trace_chunk(begin, std::min(count, begin + kBlock));
    });
  for (std::thread& worker : workers) worker.join();
}

// ---- Collecting Google Benchmark's results for the summary ------------------------------

// A run that stopped with an error: Google Benchmark 1.7 (Debian 12) says so in
// Run::error_occurred, 1.8 and later (Debian 13) in Run::skipped. The overload whose member
// exists is the one that compiles.
template <typename BenchmarkRun>
auto run_failed(const BenchmarkRun& run, int) -> decltype(static_cast<bool>(run.skipped)) {
  return static_cast<bool>(run.skipped);
}
template <typename BenchmarkRun>
auto run_failed(const BenchmarkRun& run, long) -> decltype(static_cast<bool>(run.error_occurred)) {
  return static_cast<bool>(run.error_occurred);
}

class CollectingReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    // Keyed by the registered name (without "/iterations:3", "/real_time"); with
    // --benchmark_repetitions the fastest repetition is kept: the least disturbed by load.
    for (const Run& run : runs) {
      if (run_failed(run, 0) || run.iterations <= 0 || run.run_type != Run::RT_Iteration) continue;
      const double s = run.real_accumulated_time / static_cast<double>(run.iterations);
      const auto [it, inserted] = seconds_per_iteration.emplace(run.run_name.function_name, s);
      if (!inserted) it->second = std::min(it->second, s);
    }
  }
  std::map<std::string, double> seconds_per_iteration;
};

// One row of the summary: what was traced, and its exact work.
struct TraceRow {
  std::string mesh, rays, query, accelerator;
  int threads;
  std::size_t ray_count;  // rays traced per iteration
  double nodes_per_ray, triangles_per_ray;
  bool has_counts;
};

struct Fixture {
  TestMesh mesh;
  std::vector<RaySet> ray_sets;
  std::vector<ReferenceBvh> trees;
};

std::string trace_name(const std::string& mesh, const std::string& rays, const std::string& query,
                       const std::string& accelerator, int threads) {
  return "trace/" + mesh + "/" + rays + "/" + query + "/" + accelerator + "/threads:" + std::to_string(threads);
}

// Compares closest-hit distances ray by ray; returns the rays that disagree.
std::vector<std::size_t> disagreements(const std::vector<float>& a, const std::vector<float>& b, std::size_t stride) {
  std::vector<std::size_t> bad;
  for (std::size_t i = 0; i < a.size(); i += stride) {
    const bool hit_a = a[i] < kInfinity, hit_b = b[i] < kInfinity;
    if (hit_a != hit_b || (hit_a && std::fabs(a[i] - b[i]) > 1e-4f * std::max(1.0f, a[i]))) bad.push_back(i);
  }
  return bad;
}

// ---- Embree as the program uses it --------------------------------------------------------

// One single-threaded device and one scene per fixture; make_embree returns nullptr when
// CMake did not find Embree (then every ratio prints as n/a).
class Embree {
 public:
#ifdef RAYLAB_HAVE_EMBREE
  explicit Embree(const std::vector<std::unique_ptr<Fixture>>& fixtures) : device_(embree_device(1)) {
    for (const auto& f : fixtures) {
      scenes_.push_back(std::make_unique<EmbreeScene>());
      build_embree(*scenes_.back(), device_, f->mesh);
      fixtures_.push_back(f.get());
    }
  }
  ~Embree() {
    scenes_.clear();
    rtcReleaseDevice(device_);
  }
  Embree(const Embree&) = delete;
  Embree& operator=(const Embree&) = delete;

  void trace(const Fixture& f, const std::vector<Ray>& rays, std::size_t begin, std::size_t end, bool any_hit,
             float* t_out) const {
    trace_embree(scene_of(f), rays, begin, end, any_hit, t_out);
  }
  void time_build(const Fixture& f) const {
    EmbreeScene scene;
    build_embree(scene, device_, f.mesh);
  }

 private:
  const EmbreeScene& scene_of(const Fixture& f) const {
    const auto it = std::find(fixtures_.begin(), fixtures_.end(), &f);
    return *scenes_[static_cast<std::size_t>(it - fixtures_.begin())];
  }
  RTCDevice device_;
  std::vector<std::unique_ptr<EmbreeScene>> scenes_;
  std::vector<const Fixture*> fixtures_;
#else
  void trace(const Fixture&, const std::vector<Ray>&, std::size_t, std::size_t, bool, float*) const {}
  void time_build(const Fixture&) const {}
#endif
};

std::unique_ptr<Embree> make_embree([[maybe_unused]] const std::vector<std::unique_ptr<Fixture>>& fixtures) {
#ifdef RAYLAB_HAVE_EMBREE
  return std::make_unique<Embree>(fixtures);
#else
  return nullptr;
#endif
}

// ---- The program, step by step -----------------------------------------------------------

struct Options {
  std::uint32_t large_triangles = 1000000;
  int threads = 1;               // the second thread count of the traversal series
  bool render = true;            // time the renderer on the scenes too
  std::vector<char*> benchmark_args;  // the rest, for Google Benchmark
};

Options parse_options(int argc, char** argv) {
  Options options;
  options.benchmark_args.push_back(argv[0]);
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--triangles") && i + 1 < argc) options.large_triangles = static_cast<std::uint32_t>(std::atol(argv[++i]));
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) options.threads = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--no-render")) options.render = false;
    else options.benchmark_args.push_back(argv[i]);
  }
  return options;
}

// The bunny and the generated sphere, with their ray sets and reference trees.
std::vector<std::unique_ptr<Fixture>> make_fixtures(std::uint32_t large_triangles) {
  std::vector<std::unique_ptr<Fixture>> fixtures;
  const TriangleMesh bunny = load_obj_mesh(std::string(RAYLAB_SOURCE_DIR) + "/scenes/bunny.obj");
  fixtures.push_back(std::make_unique<Fixture>(Fixture{make_test_mesh("bunny", bunny, true), {}, {}}));
  const TriangleMesh sphere = make_displaced_sphere(large_triangles, 1.0f, 1);
  const std::string sphere_name = "sphere" + std::to_string(sphere.triangle_count() / 1000) + "k";
  fixtures.push_back(std::make_unique<Fixture>(Fixture{make_test_mesh(sphere_name, sphere, false), {}, {}}));
  for (auto& f : fixtures) {
    f->ray_sets.push_back(primary_rays(f->mesh.bounds));
    f->ray_sets.push_back(random_rays(f->mesh.bounds, 20260101));
    for (bool sah : {false, true}) {
      f->trees.push_back(build_reference(f->mesh, sah));
      f->trees.push_back(tested_by_calls(f->trees.back()));
    }
    f->trees.push_back(collapsed(f->trees[2], true));  // the SAH tree
    f->trees.push_back(collapsed(f->trees[2], false));
    if (std::optional<ReferenceBvh> eight_wide = collapsed8(f->trees[2])) f->trees.push_back(std::move(*eight_wide));
  }
  return fixtures;
}

void print_trees(const Fixture& f) {
  for (const ReferenceBvh& tree : f.trees) {
    if (tree.tested_by_calls()) continue;  // the tree printed just before
    if (tree.wide) {
      std::printf("  %-12s %-15s %9zu triangles  %9zu nodes of 4 children at most\n", f.mesh.name.c_str(),
                  tree.name.c_str(), f.mesh.triangle_count(), tree.wide->nodes.size());
      continue;
    }
#if RAYLAB_AVX2_COMPILES  // (tree.wide8 is never set without it)
    if (tree.wide8) {
      std::printf("  %-12s %-15s %9zu triangles  %9zu nodes of 8 children at most\n", f.mesh.name.c_str(),
                  tree.name.c_str(), f.mesh.triangle_count(),
                  static_cast<const reference::Bvh8*>(tree.wide8.get())->nodes.size());
      continue;
    }
#endif
    std::printf("  %-12s %-15s %9zu triangles  %9zu nodes  depth %2d  SAH cost %8.2f\n",
                f.mesh.name.c_str(), tree.name.c_str(), f.mesh.triangle_count(), tree.bvh.nodes.size(),
                bvh_depth(tree.bvh), bvh_sah_cost(tree.bvh));
  }
}

// What the BVH answers are checked against: brute force on the small mesh, else Embree, else
// the first tree. Adds the brute force and Embree rows (with their work) to `rows`.
struct Oracle {
  std::string name;  // "" until there is one
  std::vector<float> t;
  std::size_t stride = 1;
};

Oracle trace_oracle(const Fixture& f, const RaySet& set, bool any_hit, const Embree* embree,
                    std::vector<TraceRow>& rows) {
  const std::string query = any_hit ? "any" : "closest";
  Oracle oracle{"", std::vector<float>(set.rays.size(), kInfinity), 1};
  if (f.mesh.brute_force) {
    BvhTraversalStats stats;
    trace_brute_force(f.mesh, set.rays, any_hit, oracle.t.data(), stats);
    oracle.name = "brute force";
    oracle.stride = kBruteForceStride;
    const std::size_t traced = (set.rays.size() + oracle.stride - 1) / oracle.stride;
    rows.push_back({f.mesh.name, set.name, query, "brute", 1, traced, 0.0,
                    static_cast<double>(stats.primitives_tested) / static_cast<double>(traced), true});
  }
  if (embree != nullptr) {
    std::vector<float> embree_t(set.rays.size(), kInfinity);
    embree->trace(f, set.rays, 0, set.rays.size(), any_hit, embree_t.data());
    rows.push_back({f.mesh.name, set.name, query, "embree", 1, set.rays.size(), 0.0, 0.0, false});
    if (!f.mesh.brute_force) oracle = {"Embree", std::move(embree_t), 1};
  }
  return oracle;
}

// Prints how many rays `t` (one tree's answers) disagree with the oracle on, and explains the
// first three by brute force: a lost hit, or a triangle-test difference (e.g. a shared edge).
void report_disagreements(const Fixture& f, const ReferenceBvh& tree, const RaySet& set, bool any_hit,
                          const std::vector<float>& t, Oracle oracle) {
  // Any hit: only "hit or not" must agree.
  std::vector<float> compared = t;
  if (any_hit)
    for (std::size_t i = 0; i < t.size(); ++i) {
      compared[i] = t[i] < kInfinity ? 0.0f : kInfinity;
      oracle.t[i] = oracle.t[i] < kInfinity ? 0.0f : kInfinity;
    }
  const std::vector<std::size_t> bad = disagreements(compared, oracle.t, oracle.stride);
  std::printf("  %-12s %-15s %-7s %-7s vs %-12s: %zu of %zu rays disagree\n", f.mesh.name.c_str(),
              tree.name.c_str(), set.name.c_str(), any_hit ? "any" : "closest", oracle.name.c_str(), bad.size(),
              set.rays.size() / oracle.stride);
  for (std::size_t k = 0; k < std::min<std::size_t>(bad.size(), 3); ++k) {
    const std::size_t i = bad[k];
    std::vector<float> brute_t(1, kInfinity);
    BvhTraversalStats ignored;
    trace_brute_force(f.mesh, {set.rays[i]}, any_hit, brute_t.data(), ignored);
    const bool brute_agrees = (brute_t[0] < kInfinity) == (t[i] < kInfinity) && (!(t[i] < kInfinity) || brute_t[0] == t[i]);
    std::printf("      ray %zu: this BVH t = %.9g, %s t = %.9g, brute force (stage 03 test) t = %.9g: %s\n", i,
                compared[i], oracle.name.c_str(), oracle.t[i], any_hit && brute_t[0] < kInfinity ? 0.0f : brute_t[0],
                brute_agrees ? "the BVH agrees with brute force (a triangle-test difference)" : "the BVH LOST A HIT <-- CHECK");
  }
}

// Untimed, single-threaded: every tree's answers against the oracle, and the exact work per
// ray of every accelerator (the rows of the summary).
void check_and_count(const Fixture& f, const Embree* embree, std::vector<TraceRow>& rows) {
  for (const RaySet& set : f.ray_sets)
    for (bool any_hit : {false, true}) {
      Oracle oracle = trace_oracle(f, set, any_hit, embree, rows);
      std::vector<float> inline_t;  // the tree before a "-calls" tree: the same tree, inlined tests
      for (const ReferenceBvh& tree : f.trees) {
        std::vector<float> t(set.rays.size(), kInfinity);
        BvhTraversalStats stats;
        trace_reference(tree, set.rays, 0, set.rays.size(), any_hit, t.data(), stats);
        if (tree.tested_by_calls()) {
          // The inlined test must give the stage function's bits: compared exactly.
          std::size_t differ = 0;
          for (std::size_t i = 0; i < t.size(); ++i) differ += t[i] != inline_t[i] ? 1 : 0;
          std::printf("  %-12s %-15s %-7s %-7s vs inlined tests: %zu of %zu rays differ%s\n", f.mesh.name.c_str(),
                      tree.name.c_str(), set.name.c_str(), any_hit ? "any" : "closest", differ, t.size(),
                      differ == 0 ? "" : " <-- CHECK");
        }
        inline_t = t;
        const auto n = static_cast<double>(set.rays.size());
        rows.push_back({f.mesh.name, set.name, any_hit ? "any" : "closest", tree.name, 1, set.rays.size(),
                        static_cast<double>(stats.nodes_visited) / n, static_cast<double>(stats.primitives_tested) / n,
                        true});
        if (oracle.name.empty()) {  // no Embree, no brute force: the first tree is the oracle
          oracle = {f.trees.front().name + " BVH", t, 1};
          if (&tree == &f.trees.front()) continue;
        }
        if (!tree.tested_by_calls()) report_disagreements(f, tree, set, any_hit, t, oracle);
      }
    }
}

void check_invariants(const Fixture& f) {
  for (const ReferenceBvh& tree : f.trees) {
    if (tree.tested_by_calls() || tree.wide || tree.wide8) continue;  // the tree checked just before
    // The tree's primitives are now in leaf order: their boxes in that order.
    std::vector<Bounds3> boxes(tree.corners.size() / 3);
    for (std::size_t i = 0; i < boxes.size(); ++i)
      for (int k = 0; k < 3; ++k) boxes[i].extend(tree.corners[3 * i + k]);
    const std::string problem = bvh_invariant_violation(tree.bvh, boxes, kLeafSize);
    std::printf("  %-12s %-7s invariants: %s\n", f.mesh.name.c_str(), tree.name.c_str(),
                problem.empty() ? "all hold" : problem.c_str());
  }
}

void register_builds(const Fixture* f, const Embree* embree) {
  const int iterations = f->mesh.triangle_count() > 100000 ? 3 : 50;
  auto boxes = std::make_shared<std::vector<Bounds3>>(triangle_boxes(f->mesh));
  for (bool sah : {false, true})
    benchmark::RegisterBenchmark(("build/" + f->mesh.name + (sah ? "/sah" : "/median")).c_str(),
                                 [boxes, sah](benchmark::State& state) {
                                   for (auto _ : state) {
                                     Bvh bvh = sah ? build_bvh_sah(*boxes, kLeafSize) : build_bvh(*boxes, kLeafSize);
                                     benchmark::DoNotOptimize(bvh.nodes.data());
                                   }
                                 })
        ->Unit(benchmark::kMillisecond)->Iterations(iterations);
  if (embree != nullptr)
    benchmark::RegisterBenchmark(("build/" + f->mesh.name + "/embree").c_str(),
                                 [f, embree](benchmark::State& state) {
                                   for (auto _ : state) embree->time_build(*f);
                                 })
        ->Unit(benchmark::kMillisecond)->Iterations(iterations);
}

// Each timed iteration traces the whole ray set, spread over thread_count threads.
template <typename TraceChunk>
void register_trace(const std::string& name, std::size_t ray_count, int thread_count, TraceChunk trace_chunk) {
  benchmark::RegisterBenchmark(name.c_str(), [ray_count, thread_count, trace_chunk](benchmark::State& state) {
    for (auto _ : state) parallel_for_chunks(ray_count, thread_count, trace_chunk);
  })->Unit(benchmark::kMillisecond)->UseRealTime();
}

void register_traces(const Fixture* f, const Embree* embree, int threads) {
  for (const RaySet& set : f->ray_sets) {
    const RaySet* rays = &set;
    for (bool any_hit : {false, true}) {
      const std::string query = any_hit ? "any" : "closest";
      if (f->mesh.brute_force)
        benchmark::RegisterBenchmark(trace_name(f->mesh.name, set.name, query, "brute", 1).c_str(),
                                     [f, rays, any_hit](benchmark::State& state) {
                                       for (auto _ : state) {
                                         BvhTraversalStats stats;
                                         trace_brute_force(f->mesh, rays->rays, any_hit, nullptr, stats);
                                       }
                                     })
            ->Unit(benchmark::kMillisecond);
      for (int thread_count : {1, threads}) {
        if (embree != nullptr)
          register_trace(trace_name(f->mesh.name, set.name, query, "embree", thread_count), rays->rays.size(),
                         thread_count, [f, embree, rays, any_hit](std::size_t begin, std::size_t end) {
                           embree->trace(*f, rays->rays, begin, end, any_hit, nullptr);
                         });
        for (const ReferenceBvh& tree : f->trees) {
          const ReferenceBvh* tree_pointer = &tree;
          register_trace(trace_name(f->mesh.name, set.name, query, tree.name, thread_count), rays->rays.size(),
                         thread_count, [tree_pointer, rays, any_hit](std::size_t begin, std::size_t end) {
                           BvhTraversalStats stats;
                           trace_reference(*tree_pointer, rays->rays, begin, end, any_hit, nullptr, stats);
                         });
        }
        if (threads == 1) break;  // {1, 1}: once
      }
    }
  }
}

using SecondsByName = std::map<std::string, double>;

double seconds_of(const SecondsByName& seconds, const std::string& name) {
  const auto it = seconds.find(name);
  return it == seconds.end() ? 0.0 : it->second;
}

void print_build_summary(const std::vector<std::unique_ptr<Fixture>>& fixtures, const SecondsByName& seconds) {
  std::printf("\nBuild times (wall clock; Embree: a device of threads=1, default quality; the reference's builders\n"
              "build the top subtrees of a tree of 64k primitives or more on every core, %u here):\n",
              std::max(1u, std::thread::hardware_concurrency()));
  std::printf("  %-12s %-8s %10s %12s\n", "mesh", "builder", "ms", "vs Embree");
  for (const auto& f : fixtures)
    for (const char* builder : {"median", "sah", "embree"}) {
      const double s = seconds_of(seconds, "build/" + f->mesh.name + "/" + builder);
      const double e = seconds_of(seconds, "build/" + f->mesh.name + "/embree");
      if (s <= 0.0) continue;
      char ratio[32] = "n/a";
      if (e > 0.0) std::snprintf(ratio, sizeof ratio, "%.2fx", s / e);
      std::printf("  %-12s %-8s %10.2f %12s\n", f->mesh.name.c_str(), builder, s * 1e3, ratio);
    }
}

// One line of the traversal summary; false if that run was not timed (filtered out).
bool print_trace_row(const TraceRow& row, int thread_count, const std::vector<TraceRow>& rows,
                     const SecondsByName& seconds) {
  const double s = seconds_of(seconds, trace_name(row.mesh, row.rays, row.query, row.accelerator, thread_count));
  const double e = seconds_of(seconds, trace_name(row.mesh, row.rays, row.query, "embree", thread_count));
  if (s <= 0.0) return false;
  // Per ray: brute force traces a subset of the rays, Embree always the whole set.
  const double per_ray = s / static_cast<double>(row.ray_count);
  double embree_per_ray = 0.0;
  for (const TraceRow& other : rows)
    if (other.mesh == row.mesh && other.rays == row.rays && other.query == row.query && other.accelerator == "embree")
      embree_per_ray = e / static_cast<double>(other.ray_count);
  char ratio[32] = "n/a", nodes[32] = "-", triangles[32] = "-";
  if (embree_per_ray > 0.0) std::snprintf(ratio, sizeof ratio, "%.2fx", per_ray / embree_per_ray);
  if (row.has_counts) {
    if (row.accelerator != "brute") std::snprintf(nodes, sizeof nodes, "%.1f", row.nodes_per_ray);
    std::snprintf(triangles, sizeof triangles, "%.1f", row.triangles_per_ray);
  }
  std::printf("  %-12s %-8s %-8s %-7d %-15s %9.2f %12s %11s %11s\n", row.mesh.c_str(), row.rays.c_str(),
              row.query.c_str(), thread_count, row.accelerator.c_str(), 1e-6 / per_ray, ratio, nodes, triangles);
  return true;
}

void print_trace_summary(const std::vector<TraceRow>& rows, int threads, const SecondsByName& seconds) {
  std::printf("\nTraversal (time vs Embree: this accelerator's time per ray / Embree's, same rays,\n"
              "same threads; nodes and triangles per ray are exact counts, single-threaded pass):\n");
  std::printf("  %-12s %-8s %-8s %-7s %-15s %9s %12s %11s %11s\n", "mesh", "rays", "query", "threads", "accel",
              "Mrays/s", "vs Embree", "nodes/ray", "tris/ray");
  for (const TraceRow& row : rows) {
    if (!print_trace_row(row, 1, rows, seconds)) continue;
    if (threads > 1 && row.accelerator != "brute") print_trace_row(row, threads, rows, seconds);
  }
}

// The whole renderer (raylab-reference render, without writing the image) on the course's
// scenes (Whitted, the bunny, the Cornell box path traced at 1 sample per pixel), on 1 and 2
// threads, and on 1 thread with the geometry of a student's program (a median tree per mesh, a
// call per triangle): rays per second as the renderer counts them, the fastest of three
// renders, and the speed-ups measured in the same run.
void print_render_summary() {
  std::printf("\nRenderer (raylab-reference render, scene size and integrator, 1 sample per pixel, no image written;\n"
              "fastest of 3; \"reference\": raylab-reference's geometry, one SAH tree over every triangle, %s,\n"
              "triangles tested inlined; \"calls\": a student's program's, a median tree per mesh and a call per\n"
              "triangle; speed-up: against 1 thread, reference; the path tracer counts its camera rays only, so\n"
              "the Cornell box's Mrays/s are millions of paths per second):\n",
              reference::eight_wide_tree_runs_here() ? "8 wide" : "4 wide");
  std::printf("  %-8s %-10s %8s %-9s %9s %10s %9s\n", "scene", "size", "threads", "geometry", "seconds", "Mrays/s",
              "speed-up");
  for (const char* name : {"whitted", "bunny", "cornell"}) {
    const Scene scene = load_scene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/" + name + ".json");
    double one_thread_seconds = 0.0;
    for (const auto& [threads, inlined] : {std::pair{1, true}, std::pair{2, true}, std::pair{1, false}}) {
      RenderSettings settings;
      settings.integrator = integrator_from_name(scene.integrator).value_or(IntegratorKind::Whitted);  // cornell: path, 1 spp
      settings.max_depth = scene.max_depth;
      settings.threads = threads;
      if (inlined) settings.tracing.own_tree = &reference::build_fast_tree;  // as raylab-reference renders
      RenderStats best;
      for (int run = 0; run < 3; ++run) {
        RenderStats stats;
        benchmark::DoNotOptimize(render(scene, settings, &stats));
        if (run == 0 || stats.seconds < best.seconds) best = stats;
      }
      if (threads == 1 && inlined) one_thread_seconds = best.seconds;
      std::printf("  %-8s %4dx%-5d %8d %-9s %9.3f %10.2f %8.2fx\n", name, scene.camera.width, scene.camera.height,
                  threads, inlined ? "reference" : "calls", best.seconds,
                  static_cast<double>(best.work.rays()) / best.seconds * 1e-6, one_thread_seconds / best.seconds);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options = parse_options(argc, argv);
  int benchmark_argc = static_cast<int>(options.benchmark_args.size());
  benchmark::Initialize(&benchmark_argc, options.benchmark_args.data());

  std::vector<std::unique_ptr<Fixture>> fixtures;
  try {
    fixtures = make_fixtures(options.large_triangles);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raylab-bench-bvh: %s\n", e.what());
    return 1;
  }
  std::unique_ptr<Embree> embree = make_embree(fixtures);  // nullptr without Embree

  std::vector<TraceRow> rows;
  std::printf("raylab-bench-bvh: leaf size %d, %d x %d primary rays, %zu random rays, brute force on every %zu-th ray\n",
              kLeafSize, kPrimaryWidth, kPrimaryHeight, kRandomRayCount, kBruteForceStride);
  std::printf("\nTrees and correctness (closest hits compared ray by ray):\n");
  for (const auto& f : fixtures) {
    print_trees(*f);
    check_and_count(*f, embree.get(), rows);
    check_invariants(*f);
  }
  std::printf("\n");
  std::fflush(stdout);

  for (const auto& f : fixtures) {
    register_builds(f.get(), embree.get());
    register_traces(f.get(), embree.get(), options.threads);
  }
  CollectingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();

  print_build_summary(fixtures, reporter.seconds_per_iteration);
  print_trace_summary(rows, options.threads, reporter.seconds_per_iteration);
  if (options.render) print_render_summary();
  return 0;
}
