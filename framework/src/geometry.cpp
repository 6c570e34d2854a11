#include "raylab/geometry.h"

#include "raylab/bvh_tools.h"
#include "raylab/error.h"
#include "raylab/stages/02_sphere.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>

namespace raylab {

// What the primitive tests of one query share (the `void* context` of PrimitiveIntersector).
struct SceneGeometry::Query {
  const SceneGeometry* geometry;
  HitRecord* record;
  bool any_hit;
  const Triangle* mesh_triangles = nullptr;  // the mesh being traversed: its first triangle
  std::uint32_t mesh_first_triangle = 0;     // ... and that triangle's index in triangles_
};

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

// A student's build_bvh may return a tree that would send the traversal out of its arrays:
// stop with the broken rule in words rather than crash (or render garbage) later.
void check_tree(const Bvh& bvh, const std::vector<Bounds3>& boxes, const std::string& what) {
  const std::string problem = bvh_invariant_violation(bvh, boxes, SceneGeometry::kBvhLeafSize);
  if (!problem.empty())
    throw std::logic_error("stage 05_bvh: build_bvh over " + std::to_string(boxes.size()) + " boxes (" +
                           what + ") returned a broken tree: " + problem +
                           " (the autograder's stage 5 tests say more)");
}

Bounds3 triangle_bounds(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  Bounds3 box;
  box.extend(p0);
  box.extend(p1);
  box.extend(p2);
  return box;
}

}  // namespace

SceneGeometry::SceneGeometry(const Scene& scene, Acceleration acceleration, TriangleTest triangle_test)
    : scene_(scene), spheres_(scene.spheres),
      intersect_triangle_(triangle_test == TriangleTest::Watertight ? intersect_ray_triangle_watertight
                                                                     : intersect_ray_triangle) {
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    MeshPart part;
    part.first_triangle = static_cast<std::uint32_t>(triangles_.size());
    for (std::uint32_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const Triangle triangle{mesh.positions[mesh.indices[i]], mesh.positions[mesh.indices[i + 1]],
                              mesh.positions[mesh.indices[i + 2]], m, i};
      part.bounds.extend(triangle_bounds(triangle.p0, triangle.p1, triangle.p2));
      triangles_.push_back(triangle);
    }
    part.triangle_count = static_cast<std::uint32_t>(triangles_.size()) - part.first_triangle;
    meshes_.push_back(std::move(part));
  }
  if (acceleration == Acceleration::BvhAlways) brute_force_limit_ = 0;
  if (acceleration != Acceleration::BruteForce) build_bvhs();
}

void SceneGeometry::build_bvhs() {
  try {
    for (MeshPart& mesh : meshes_) {
      if (mesh.triangle_count <= brute_force_limit_) continue;
      Triangle* first = triangles_.data() + mesh.first_triangle;
      std::vector<Bounds3> boxes;
      boxes.reserve(mesh.triangle_count);
      for (std::uint32_t i = 0; i < mesh.triangle_count; ++i)
        boxes.push_back(triangle_bounds(first[i].p0, first[i].p1, first[i].p2));
      mesh.bvh = build_bvh(boxes, kBvhLeafSize);
      check_tree(mesh.bvh, boxes, scene_.meshes[first->mesh].name);
      // Store the triangles in leaf order, so that a leaf's triangles are adjacent in memory;
      // the BVH's primitive_order then becomes the identity.
      std::vector<Triangle> reordered;
      reordered.reserve(mesh.triangle_count);
      for (std::uint32_t i = 0; i < mesh.triangle_count; ++i) {
        reordered.push_back(first[mesh.bvh.primitive_order[i]]);
        mesh.bvh.primitive_order[i] = i;
      }
      std::copy(reordered.begin(), reordered.end(), first);
    }
    const std::size_t object_count = spheres_.size() + meshes_.size();
    if (object_count > brute_force_limit_) {
      std::vector<Bounds3> boxes;
      boxes.reserve(object_count);
      for (const Sphere& sphere : spheres_)
        boxes.emplace_back(sphere.center - glm::vec3(sphere.radius), sphere.center + glm::vec3(sphere.radius));
      for (const MeshPart& mesh : meshes_) boxes.push_back(mesh.bounds);
      objects_bvh_ = build_bvh(boxes, kBvhLeafSize);
      check_tree(objects_bvh_, boxes, "the scene's objects");
    }
    // A traversal needs the box test (stage 04_box) and intersect_bvh: find out now, with one
    // query, whether they are still stubs, rather than in the middle of the render.
    // The probe's intersector hits nothing, so that only stages 04 and 05 run here.
    const Bvh* probe_bvh = !objects_bvh_.nodes.empty() ? &objects_bvh_ : nullptr;
    for (const MeshPart& mesh : meshes_)
      if (!probe_bvh && !mesh.bvh.nodes.empty()) probe_bvh = &mesh.bvh;
    if (probe_bvh) {
      Ray probe;
      probe.origin = probe_bvh->nodes[0].bounds.centroid();  // inside the root's box
      probe.direction = glm::vec3(0.0f, 0.0f, 1.0f);
      (void)intersect_ray_box(probe, ray_direction_inverse_of(probe), probe_bvh->nodes[0].bounds);
      const PrimitiveIntersector hits_nothing{
          [](void*, const Ray&, std::uint32_t) -> std::optional<float> { return std::nullopt; }, nullptr};
      BvhTraversalStats stats;
      (void)intersect_bvh(*probe_bvh, probe, hits_nothing, /*any_hit=*/false, stats);
    }
  } catch (const NotImplemented& error) {
    for (MeshPart& mesh : meshes_) mesh.bvh = Bvh();
    objects_bvh_ = Bvh();
    fallback_stage_ = error.stage_id();
  }
}

bool SceneGeometry::record_is_of_object(const HitRecord& record, std::uint32_t object, float t_hit) const {
  if (record.t_hit != t_hit) return false;
  if (object < spheres_.size()) return record.kind == Kind::Sphere && record.index == object;
  if (object - spheres_.size() >= meshes_.size()) return false;
  const MeshPart& mesh = meshes_[object - spheres_.size()];
  return record.kind == Kind::Triangle && record.index >= mesh.first_triangle &&
         record.index - mesh.first_triangle < mesh.triangle_count;
}

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
    for (const Sphere& sphere : spheres_) hits += intersect_ray_sphere(sample, sphere.center, sphere.radius) ? 1 : 0;
    for (const Triangle& tri : triangles_) hits += intersect_triangle_(sample, tri.p0, tri.p1, tri.p2) ? 1 : 0;
    ++passes;
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (seconds < 2e-3 && passes < 100000);
  (void)hits;  // counted only so that the tests are not optimised away
  const double pass_seconds = seconds / static_cast<double>(passes);
  const double pixels = static_cast<double>(scene_.camera.width) * scene_.camera.height;
  const double rays = pixels * (1.0 + static_cast<double>(scene_.lights.size()));
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
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

std::size_t SceneGeometry::bvh_count() const {
  std::size_t count = objects_bvh_.nodes.empty() ? 0 : 1;
  for (const MeshPart& mesh : meshes_) count += mesh.bvh.nodes.empty() ? 0 : 1;
  return count;
}

// ---- The primitive tests ----------------------------------------------------------------
// A traversal may call the tests in any order and with any t_max (a correct closest-hit
// traversal passes the closest hit so far, but one that visits both children with the
// original t_max also finds the right answer). So a test records a hit's details only when
// it is closer than the query's record so far, and after a traversal the record is checked
// against the primitive it returned: the framework shades what the traversal returned.

std::optional<float> SceneGeometry::test_triangle(void* context, const Ray& ray, std::uint32_t triangle) {
  Query& query = *static_cast<Query*>(context);
  const Triangle& tri = query.mesh_triangles[triangle];
  const std::optional<TriangleHit> hit = query.geometry->intersect_triangle_(ray, tri.p0, tri.p1, tri.p2);
  if (!hit) return std::nullopt;
  if (hit->t_hit < query.record->t_hit) {
    query.record->kind = Kind::Triangle;
    query.record->index = query.mesh_first_triangle + triangle;
    query.record->t_hit = hit->t_hit;
    query.record->triangle_hit = *hit;
  }
  return hit->t_hit;
}

std::optional<float> SceneGeometry::test_object(void* context, const Ray& ray, std::uint32_t object) {
  Query& query = *static_cast<Query*>(context);
  return query.geometry->intersect_object(object, ray, query);
}

std::optional<float> SceneGeometry::intersect_mesh(const MeshPart& mesh, const Ray& ray, Query& query) const {
  query.mesh_triangles = triangles_.data() + mesh.first_triangle;
  query.mesh_first_triangle = mesh.first_triangle;
  if (!mesh.bvh.nodes.empty()) {
    BvhTraversalStats stats;
    const PrimitiveIntersector intersector{&SceneGeometry::test_triangle, &query};
    if (query.any_hit) {
      const std::optional<BvhHit> hit = intersect_bvh(mesh.bvh, ray, intersector, true, stats);
      return hit ? std::optional<float>(hit->t_hit) : std::nullopt;
    }
    // This mesh's own closest hit is recorded apart from the query's (which may hold a closer
    // hit on another object, when the traversal over the objects did not lower t_max).
    HitRecord* const query_record = query.record;
    HitRecord mesh_record;
    query.record = &mesh_record;
    const std::optional<BvhHit> hit = intersect_bvh(mesh.bvh, ray, intersector, false, stats);
    query.record = query_record;
    if (!hit || hit->primitive >= mesh.triangle_count) return std::nullopt;
    const std::uint32_t returned = mesh.first_triangle + hit->primitive;
    if (mesh_record.kind != Kind::Triangle || mesh_record.index != returned || mesh_record.t_hit != hit->t_hit) {
      // The traversal returned another triangle than the closest one reported to the test
      // (a tie, or a traversal that is wrong): shade the one it returned.
      const Triangle& tri = triangles_[returned];
      const std::optional<TriangleHit> details = intersect_triangle_(ray, tri.p0, tri.p1, tri.p2);
      if (!details) return std::nullopt;
      mesh_record.kind = Kind::Triangle;
      mesh_record.index = returned;
      mesh_record.triangle_hit = *details;
    }
    mesh_record.t_hit = hit->t_hit;
    if (hit->t_hit < query_record->t_hit) *query_record = mesh_record;
    return hit->t_hit;
  }
  Ray search = ray;
  std::optional<float> closest;
  for (std::uint32_t i = 0; i < mesh.triangle_count; ++i) {
    if (const std::optional<float> t = test_triangle(&query, search, i)) {
      search.t_max = *t;
      closest = t;
      if (query.any_hit) break;
    }
  }
  return closest;
}

std::optional<float> SceneGeometry::intersect_object(std::uint32_t object, const Ray& ray, Query& query) const {
  if (object < spheres_.size()) {
    const Sphere& sphere = spheres_[object];
    const std::optional<float> t = intersect_ray_sphere(ray, sphere.center, sphere.radius);
    if (t && *t < query.record->t_hit) {
      query.record->kind = Kind::Sphere;
      query.record->index = object;
      query.record->t_hit = *t;
    }
    return t;
  }
  return intersect_mesh(meshes_[object - spheres_.size()], ray, query);
}

std::optional<float> SceneGeometry::intersect_objects(const Ray& ray, Query& query) const {
  if (!objects_bvh_.nodes.empty()) {
    BvhTraversalStats stats;
    const PrimitiveIntersector intersector{&SceneGeometry::test_object, &query};
    const std::optional<BvhHit> hit = intersect_bvh(objects_bvh_, ray, intersector, query.any_hit, stats);
    if (!hit || query.any_hit) return hit ? std::optional<float>(hit->t_hit) : std::nullopt;
    if (!record_is_of_object(*query.record, hit->primitive, hit->t_hit)) {
      // Not the object whose hit the tests recorded as the closest: shade the returned one.
      HitRecord returned;
      Query again{this, &returned, /*any_hit=*/false};
      if (hit->primitive >= spheres_.size() + meshes_.size() || !intersect_object(hit->primitive, ray, again))
        return std::nullopt;
      *query.record = returned;
    }
    return hit->t_hit;
  }
  // Few objects: each in turn (spheres first, as the brute force always did), t_max shrinking.
  // Written out flat, without the per-object dispatch: this is also the whole render of a
  // small scene, and of every scene while stage 5 is a stub.
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
  for (std::uint32_t i = 0; i < sphere_count; ++i) {
    if (const std::optional<float> t = intersect_ray_sphere(search, spheres[i].center, spheres[i].radius)) {
      search.t_max = *t;
      best.kind = Kind::Sphere;
      best.index = i;
      best.t_hit = *t;
    }
  }
  for (std::size_t m = 0; m < mesh_count; ++m) {
    const MeshPart& mesh = meshes[m];
    if (!mesh.bvh.nodes.empty()) {
      *query.record = HitRecord();
      if (const std::optional<float> t = intersect_mesh(mesh, search, query)) {
        search.t_max = *t;
        best = *query.record;  // intersect_mesh wrote its closest hit there
      }
      continue;
    }
    const std::uint32_t end = mesh.first_triangle + mesh.triangle_count;
    for (std::uint32_t i = mesh.first_triangle; i < end; ++i) {
      const Triangle& tri = triangles[i];
      if (const std::optional<TriangleHit> hit = intersect_triangle_(search, tri.p0, tri.p1, tri.p2)) {
        search.t_max = hit->t_hit;
        best.kind = Kind::Triangle;
        best.index = i;
        best.t_hit = hit->t_hit;
        best.triangle_hit = *hit;
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
  for (const Sphere& sphere : spheres_)
    if (intersect_ray_sphere(ray, sphere.center, sphere.radius)) return true;
  for (const MeshPart& mesh : meshes_) {
    if (!mesh.bvh.nodes.empty()) {
      if (intersect_mesh(mesh, ray, query)) return true;
      continue;
    }
    const Triangle* const first = triangles_.data() + mesh.first_triangle;
    for (std::uint32_t i = 0; i < mesh.triangle_count; ++i)
      if (intersect_triangle_(ray, first[i].p0, first[i].p1, first[i].p2)) return true;
  }
  return false;
}

std::optional<SurfaceHit> SceneGeometry::intersect(const Ray& ray) const {
  // Find the closest t first (shrinking t_max after every hit), then fill the record once.
  HitRecord record;
  Query query{this, &record, /*any_hit=*/false};
  const std::optional<float> t_hit = intersect_objects(ray, query);
  if (!t_hit || record.kind == Kind::None) return std::nullopt;
  const Kind kind = record.kind;
  const std::size_t index = record.index;
  const TriangleHit& triangle_hit = record.triangle_hit;

  SurfaceHit hit;
  hit.t_hit = *t_hit;
  if (kind == Kind::Sphere) {
    const Sphere& sphere = spheres_[index];
    // Re-project the hit point onto the surface: its error is then a few ulps (pbrt-v4 6.8.5).
    const glm::vec3 outward = glm::normalize(ray.at(hit.t_hit) - sphere.center);
    hit.point = sphere.center + sphere.radius * outward;
    hit.point_error = gamma_bound(5) * glm::abs(hit.point) + gamma_bound(5) * glm::abs(sphere.center);
    hit.geometric_normal = outward;
    hit.material = sphere.material;
  } else {
    const Triangle& tri = triangles_[index];
    const TriangleMesh& mesh = scene_.meshes[tri.mesh];
    const float b1 = triangle_hit.barycentric_b1, b2 = triangle_hit.barycentric_b2;
    const float b0 = 1.0f - b1 - b2;
    // The point from barycentrics is far more accurate than origin + t * direction.
    hit.point = b0 * tri.p0 + b1 * tri.p1 + b2 * tri.p2;
    hit.point_error = gamma_bound(7) * (glm::abs(b0 * tri.p0) + glm::abs(b1 * tri.p1) + glm::abs(b2 * tri.p2));
    const glm::vec3 normal = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    const float length = glm::length(normal);
    // A degenerate triangle has no normal; face the ray so that shading stays finite.
    hit.geometric_normal = length > 0.0f ? normal / length : -glm::normalize(ray.direction);
    if (!mesh.texcoords.empty()) {
      hit.texcoord = b0 * mesh.texcoords[mesh.indices[tri.first_index]] +
                     b1 * mesh.texcoords[mesh.indices[tri.first_index + 1]] +
                     b2 * mesh.texcoords[mesh.indices[tri.first_index + 2]];
      hit.has_texcoord = true;
    }
    hit.material = mesh.material;
  }
  return hit;
}

bool SceneGeometry::occluded(const Ray& ray) const {
  HitRecord record;
  Query query{this, &record, /*any_hit=*/true};
  return intersect_objects(ray, query).has_value();
}

}  // namespace raylab
