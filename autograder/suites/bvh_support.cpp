#include "bvh_support.h"

#include "grading.h"

#include "raylab/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>

namespace raylab::grading {
namespace {

// The grader's own test (stage_calls.h) on the mesh's triangles.
std::optional<float> test_triangle(const TestMesh& mesh, const Ray& ray, std::uint32_t primitive) {
  return grader_triangle_test(const_cast<std::vector<std::array<glm::vec3, 3>>*>(&mesh.triangles), ray, primitive);
}

TestMesh make_mesh(std::string name, std::vector<std::array<glm::vec3, 3>> triangles) {
  TestMesh mesh{std::move(name), std::move(triangles), {}};
  for (const auto& t : mesh.triangles) {
    Bounds3 box;
    for (const glm::vec3& corner : t) box.extend(corner);
    mesh.bounds.push_back(box);
  }
  return mesh;
}

std::vector<TestMesh> make_meshes() {
  std::vector<TestMesh> meshes;
  const TriangleMesh bunny = load_obj_mesh(std::string(RAYLAB_SOURCE_DIR) + "/scenes/bunny.obj");
  std::vector<std::array<glm::vec3, 3>> triangles;
  for (std::size_t i = 0; i + 2 < bunny.indices.size(); i += 3)
    triangles.push_back({bunny.positions[bunny.indices[i]], bunny.positions[bunny.indices[i + 1]],
                         bunny.positions[bunny.indices[i + 2]]});
  meshes.push_back(make_mesh("the bunny", triangles));

  Pcg32 random(505, testkit::stream_of("bvh triangle soup"));
  triangles.clear();
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 center = testkit::random_vec3(random, -10, 10);
    triangles.push_back({center + testkit::random_vec3(random, -1, 1), center + testkit::random_vec3(random, -1, 1), center + testkit::random_vec3(random, -1, 1)});
  }
  meshes.push_back(make_mesh("a random triangle soup", triangles));

  triangles.clear();
  for (int z = 0; z < 20; ++z)
    for (int x = 0; x < 20; ++x) {
      const glm::vec3 a(x, 0, z), b(x + 1, 0, z), c(x + 1, 0, z + 1), d(x, 0, z + 1);
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
  meshes.push_back(make_mesh("a flat grid (boxes of zero height)", triangles));

  triangles.assign(64, {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)});
  meshes.push_back(make_mesh("64 copies of one triangle (equal centroids)", triangles));
  return meshes;
}

}  // namespace

const std::vector<TestMesh>& bvh_test_meshes() {
  static const std::vector<TestMesh> meshes = make_meshes();
  return meshes;
}

PrimitiveIntersector intersector_for(const TestMesh& mesh) {
  return PrimitiveIntersector{grader_triangle_test, const_cast<std::vector<std::array<glm::vec3, 3>>*>(&mesh.triangles)};
}

std::optional<BvhHit> brute_force_closest(const TestMesh& mesh, const Ray& ray) {
  Ray search = ray;
  std::optional<BvhHit> best;
  for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i)
    if (const auto t = test_triangle(mesh, search, i)) {
      search.t_max = *t;
      best = BvhHit{*t, i};
    }
  return best;
}

std::vector<Ray> rays_at(const TestMesh& mesh, int count, std::uint32_t seed, bool axis_aligned) {
  Bounds3 box;
  for (const Bounds3& b : mesh.bounds) box.extend(b);
  const glm::vec3 center = 0.5f * (box.min + box.max);
  const float radius = 0.5f * glm::length(box.max - box.min) * 1.5f + 1.0f;
  Pcg32 random(seed, testkit::stream_of("bvh rays"));
  std::vector<Ray> rays;
  while (static_cast<int>(rays.size()) < count) {
    Ray ray;
    const glm::vec3 target = box.min + testkit::random_vec3(random, 0, 1) * (box.max - box.min);
    if (axis_aligned) {
      const int axis = testkit::random_integer(random, 0, 2);
      const float sign = testkit::random_integer(random, 0, 1) ? 1.0f : -1.0f;
      ray.direction = glm::vec3(0.0f);
      ray.direction[axis] = sign;
      ray.origin = target - ray.direction * radius;
    } else {
      const glm::vec3 around = testkit::random_vec3(random, -1, 1);
      if (glm::length(around) < 1e-3f) continue;
      ray.origin = center + glm::normalize(around) * radius;
      ray.direction = glm::normalize(target - ray.origin);
    }
    rays.push_back(ray);
  }
  return rays;
}

std::vector<std::uint32_t> subtree_primitive_counts(const Bvh& bvh) {
  std::vector<std::uint32_t> counts(bvh.nodes.size(), 0);
  // Children follow their parents in the array (an invariant checked elsewhere): go backwards.
  for (std::size_t i = bvh.nodes.size(); i-- > 0;) {
    const BvhNode& node = bvh.nodes[i];
    if (node.is_leaf()) counts[i] = node.primitive_count;
    else if (node.first_index + 1 < counts.size()) counts[i] = counts[node.first_index] + counts[node.first_index + 1];
  }
  return counts;
}

int compare_with_brute_force(const Bvh& bvh, const TestMesh& mesh, const std::vector<Ray>& rays, bool any_hit,
                             const char* what) {
  const PrimitiveIntersector intersector = intersector_for(mesh);
  int differences = 0;
  for (std::size_t r = 0; r < rays.size(); ++r) {
    const Ray& ray = rays[r];
    const std::optional<BvhHit> expected = brute_force_closest(mesh, ray);
    BvhTraversalStats stats;
    const std::optional<BvhHit> got = intersect_bvh(bvh, ray, intersector, any_hit, stats);
    bool ok = got.has_value() == expected.has_value();
    if (ok && got && !any_hit) ok = got->t_hit == expected->t_hit;  // same primitive test: exactly equal
    if (ok && got && any_hit) ok = got->primitive < mesh.triangles.size() && test_triangle(mesh, ray, got->primitive).has_value();
    if (ok) continue;
    if (++differences > 3) continue;
    const bool zero_component = ray.direction.x == 0 || ray.direction.y == 0 || ray.direction.z == 0;
    if (got && expected && got->t_hit > expected->t_hit)
      add_hint("returns a hit that is not the closest: keep searching after the first hit, pass t_max = the closest t so "
               "far to the tests, and skip only children whose box entry is beyond it");
    else if (got && expected)
      add_hint("returns a t closer than any real hit: return the t the primitive test reported, with its primitive");
    else if (!got && expected && zero_component)
      add_hint("misses hits of rays with zero direction components: check your box test (stage 04_box) with +-0 directions");
    else if (!got && expected)
      add_hint("misses a hit: a child was skipped although it holds a hit (is the box test right? is a leaf's every "
               "primitive tested? are the primitive indices taken from primitive_order?)");
    else
      add_hint("reports a hit where there is none: return only hits the primitive test reported");
    ADD_FAILURE() << what << " on " << mesh.name << ", ray " << r << ": " << ray << "\n  expected "
                  << (expected ? "t = " + std::to_string(expected->t_hit) + " (triangle " + std::to_string(expected->primitive) + ")" : std::string("no hit"))
                  << "\n  got      "
                  << (got ? "t = " + std::to_string(got->t_hit) + " (triangle " + std::to_string(got->primitive) + ")" : std::string("no hit"));
  }
  return differences;
}

}  // namespace raylab::grading
