// SceneGeometry, part 3 of 4: without a tree over the objects. Every object in turn (a small
// scene, or every scene while stage 04_box or 05_bvh is a stub), the any-hit form of that
// loop, and the one line that says the render is testing every primitive, with an estimate
// of how long that will take.
#include "geometry_query.h"

#include "raylab/cores.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace raylab {

namespace {

// One line, once per process, however many scenes or threads: the student should see it,
// not drown in it. `estimate` (how slow, and what to do about it) is computed only then.
template <typename Estimate>
void report_fallback_once(const std::string& stage_id, Estimate&& estimate) {
  static std::atomic<bool> reported{false};
  if (!reported.load(std::memory_order_relaxed) && !reported.exchange(true))
    std::fprintf(stderr, "raylab: stage %s not implemented yet: testing every primitive (slow)%s\n",
                 stage_id.c_str(), estimate().c_str());
}

}  // namespace

// Every ray tests every primitive: the render takes about pixels x rays per pixel x one pass
// over all primitives / threads. One pass is timed here, on the first ray, with the
// student's own sphere and triangle functions; rays per pixel is taken as 1 + the number of
// lights (a camera ray and a shadow ray per light), which reflections and refractions only
// add to: the estimate is a lower bound. Said before the render starts, with a smaller
// --width/--height that would take a few seconds.
std::string SceneGeometry::brute_force_estimate(const Ray& sample) const {
  const std::size_t primitives = spheres_.size() + triangles_.size();
  const auto start = std::chrono::steady_clock::now();
  std::size_t passes = 0, hits = 0;
  double seconds = 0.0;
  do {  // at least 2 ms of work, so that the clock's resolution does not matter
    for (const Sphere& sphere : spheres_) hits += intersect_sphere_(sample, sphere.center, sphere.radius) ? 1 : 0;
    for (const Triangle& tri : triangles_) hits += intersect_triangle_(sample, tri.p0, tri.p1, tri.p2) ? 1 : 0;
    ++passes;
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (seconds < 2e-3 && passes < 100000);
  (void)hits;  // counted only so that the tests are not optimised away
  const double pass_seconds = seconds / static_cast<double>(passes);
  const double pixels = static_cast<double>(scene_.camera.width) * scene_.camera.height;
  const double rays = pixels * (1.0 + static_cast<double>(scene_.lights.size()));
  const unsigned threads = usable_cores();
  const double estimate = rays * pass_seconds / threads;
  if (estimate < 10.0) return "";
  // A size that would take about 5 s: both sides divided by the same factor.
  const int factor = static_cast<int>(std::ceil(std::sqrt(estimate / 5.0)));
  char text[400];
  std::snprintf(text, sizeof text,
                ": %zu primitives for every ray, so this %dx%d render will take at least %.0f s on %u threads "
                "(at least %.0f rays, %.2f ms per ray); for a quick look render at --width %d --height %d "
                "(about %.0f s), or write stage 05_bvh",
                primitives, scene_.camera.width, scene_.camera.height, estimate, threads, rays, pass_seconds * 1e3,
                std::max(1, scene_.camera.width / factor), std::max(1, scene_.camera.height / factor),
                estimate / (factor * factor));
  return text;
}

// Few objects: each in turn (spheres first, as the brute force always did), t_max shrinking.
// Written out flat, without the per-object dispatch: this is also the whole render of a
// small scene, and of every scene while stage 5 is a stub.
std::optional<float> SceneGeometry::intersect_every_object(const Ray& ray, Query& query) const {
  if (!fallback_stage_.empty()) report_fallback_once(fallback_stage_, [&] { return brute_force_estimate(ray); });
  if (query.any_hit) return occluded_by_any_object(ray, query) ? std::optional<float>(ray.t_min) : std::nullopt;
  // The best hit is kept in locals (registers) and written to the record once, at the end.
  // (Array pointers and sizes in locals: the stage functions are opaque calls, after which
  // the compiler would otherwise reload them from the vectors.)
  Ray search = ray;
  HitRecord best;
  const Sphere* const spheres = spheres_.data();
  const auto sphere_count = static_cast<std::uint32_t>(spheres_.size());
  const Triangle* const triangles = triangles_.data();
  const MeshPart* const meshes = meshes_.data();
  const std::size_t mesh_count = meshes_.size();
  thread_tree_work.primitives += sphere_count;
  for (std::uint32_t i = 0; i < sphere_count; ++i) {
    if (const std::optional<float> t = intersect_sphere_(search, spheres[i].center, spheres[i].radius)) {
      search.t_max = *t;
      best.set_sphere(i, *t);
    }
  }
  for (std::size_t m = 0; m < mesh_count; ++m) {
    const MeshPart& mesh = meshes[m];
    if (mesh.has_tree()) {
      *query.record = HitRecord();
      if (const std::optional<float> t = intersect_mesh(mesh, search, query)) {
        search.t_max = *t;
        best = *query.record;  // intersect_mesh wrote its closest hit there
      }
      continue;
    }
    const std::uint32_t end = mesh.first_triangle + mesh.triangle_count;
    thread_tree_work.primitives += mesh.triangle_count;
    for (std::uint32_t i = mesh.first_triangle; i < end; ++i) {
      const Triangle& tri = triangles[i];
      if (const std::optional<TriangleHit> hit = intersect_triangle_(search, tri.p0, tri.p1, tri.p2)) {
        search.t_max = hit->t_hit;
        best.set_triangle(i, *hit);
      }
    }
  }
  if (best.kind == Kind::None) return std::nullopt;
  *query.record = best;
  return search.t_max;
}

// The any-hit form of the loops above: t_max never shrinks, so the ray is used as it is (no
// copy: a shadow ray was just written field by field, and reading it back whole would stall).
bool SceneGeometry::occluded_by_any_object(const Ray& ray, Query& query) const {
  thread_tree_work.primitives += spheres_.size();  // at most: the loops stop at the first hit
  for (const Sphere& sphere : spheres_)
    if (intersect_sphere_(ray, sphere.center, sphere.radius)) return true;
  for (const MeshPart& mesh : meshes_) {
    if (mesh.has_tree()) {
      if (intersect_mesh(mesh, ray, query)) return true;
      continue;
    }
    const Triangle* const first = triangles_.data() + mesh.first_triangle;
    thread_tree_work.primitives += mesh.triangle_count;
    for (std::uint32_t i = 0; i < mesh.triangle_count; ++i)
      if (intersect_triangle_(ray, first[i].p0, first[i].p1, first[i].p2)) return true;
  }
  return false;
}

}  // namespace raylab
