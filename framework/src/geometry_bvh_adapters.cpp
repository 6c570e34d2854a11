// SceneGeometry, part 2 of 4: the queries through the trees. The primitive tests that the
// student's intersect_bvh calls (PrimitiveIntersector adapters over a mesh's triangles and
// over the scene's objects), and the check of what a traversal returned against what the
// tests recorded, so that the framework shades the primitive the traversal returned.
#include "geometry_query.h"
#include "mesh_trees.h"

#include "raylab/stages/05_bvh.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <vector>

namespace raylab {

bool SceneGeometry::record_is_of_object(const HitRecord& record, std::uint32_t object, float t_hit) const {
  if (record.t_hit != t_hit) return false;
  if (object < spheres_.size()) return record.kind == Kind::Sphere && record.index == object;
  if (object - spheres_.size() >= meshes_.size()) return false;
  const MeshPart& mesh = meshes_[object - spheres_.size()];
  return record.kind == Kind::Triangle && record.index >= mesh.first_triangle &&
         record.index - mesh.first_triangle < mesh.triangle_count;
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
  if (hit->t_hit < query.record->t_hit) query.record->set_triangle(query.mesh_first_triangle + triangle, *hit);
  return hit->t_hit;
}

// The same, counted for walk_to.
std::optional<float> SceneGeometry::test_triangle_watched(void* context, const Ray& ray, std::uint32_t triangle) {
  Query& query = *static_cast<Query*>(context);
  ++query.watch->tests;
  if (query.mesh_first_triangle + triangle == query.watch->triangle) query.watch->tested = true;
  const std::optional<float> t = test_triangle(context, ray, triangle);
  query.watch->add(false, query.mesh_first_triangle + triangle, ray.t_max, t);
  return t;
}

std::optional<float> SceneGeometry::test_object(void* context, const Ray& ray, std::uint32_t object) {
  Query& query = *static_cast<Query*>(context);
  return query.geometry->intersect_object(object, ray, query);
}

std::optional<float> SceneGeometry::intersect_mesh(const MeshPart& mesh, const Ray& ray, Query& query) const {
  query.mesh_triangles = triangles_.data() + mesh.first_triangle;
  query.mesh_first_triangle = mesh.first_triangle;
  if (mesh.own_tree && !query.watch) {  // (walk_to's watched query tests each triangle, below)
    if (query.any_hit) return mesh.own_tree->any_hit(ray);
    std::uint32_t triangle = 0;
    TriangleHit details;
    if (!mesh.own_tree->closest_hit(ray, triangle, details) || triangle >= mesh.triangle_count) return std::nullopt;
    if (details.t_hit < query.record->t_hit) query.record->set_triangle(mesh.first_triangle + triangle, details);
    return details.t_hit;
  }
  if (mesh.tree) {
    BvhTraversalStats stats;
    PrimitiveIntersector intersector{query.watch ? &SceneGeometry::test_triangle_watched : &SceneGeometry::test_triangle,
                                     &query};
    const auto traverse = [&](bool any_hit) { return mesh.tree->traverse(ray, intersector, any_hit, stats); };
    if (query.any_hit) {
      const std::optional<BvhHit> hit = traverse(true);
      thread_tree_work.nodes += stats.nodes_visited;
      thread_tree_work.primitives += stats.primitives_tested;
      return hit ? std::optional<float>(hit->t_hit) : std::nullopt;
    }
    // This mesh's own closest hit is recorded apart from the query's (which may hold a closer
    // hit on another object, when the traversal over the objects did not lower t_max).
    HitRecord* const query_record = query.record;
    HitRecord mesh_record;
    query.record = &mesh_record;
    const std::optional<BvhHit> hit = traverse(false);
    thread_tree_work.nodes += stats.nodes_visited;
    thread_tree_work.primitives += stats.primitives_tested;
    query.record = query_record;
    if (!hit || hit->primitive >= mesh.triangle_count) return std::nullopt;
    const std::uint32_t returned = mesh.first_triangle + hit->primitive;
    if (mesh_record.kind != Kind::Triangle || mesh_record.index != returned || mesh_record.t_hit != hit->t_hit) {
      // The traversal returned another triangle than the closest one reported to the test
      // (a tie, or a traversal that is wrong): shade the one it returned.
      const Triangle& tri = triangles_[returned];
      const std::optional<TriangleHit> details = intersect_triangle_(ray, tri.p0, tri.p1, tri.p2);
      if (!details) return std::nullopt;
      mesh_record.set_triangle(returned, *details);
    }
    mesh_record.t_hit = hit->t_hit;
    if (hit->t_hit < query_record->t_hit) *query_record = mesh_record;
    return hit->t_hit;
  }
  Ray search = ray;
  std::optional<float> closest;
  thread_tree_work.primitives += mesh.triangle_count;  // at most, for an any-hit query
  for (std::uint32_t i = 0; i < mesh.triangle_count; ++i) {
    if (const std::optional<float> t =
            query.watch ? test_triangle_watched(&query, search, i) : test_triangle(&query, search, i)) {
      search.t_max = *t;
      closest = t;
      if (query.any_hit) break;
    }
  }
  return closest;
}

std::optional<float> SceneGeometry::intersect_object(std::uint32_t object, const Ray& ray, Query& query) const {
  if (object < spheres_.size()) {
    if (query.watch) {
      ++query.watch->tests;
      if (object == query.watch->sphere) query.watch->tested = true;
    }
    const Sphere& sphere = spheres_[object];
    ++thread_tree_work.primitives;
    const std::optional<float> t = intersect_sphere_(ray, sphere.center, sphere.radius);
    if (t && *t < query.record->t_hit) query.record->set_sphere(object, *t);
    if (query.watch) query.watch->add(true, object, ray.t_max, t);
    return t;
  }
  return intersect_mesh(meshes_[object - spheres_.size()], ray, query);
}

std::optional<float> SceneGeometry::intersect_objects_through_bvh(const Ray& ray, Query& query) const {
  BvhTraversalStats stats;
  const PrimitiveIntersector intersector{&SceneGeometry::test_object, &query};
  const std::optional<BvhHit> hit = intersect_bvh(objects_bvh_, ray, intersector, query.any_hit, stats);
  thread_tree_work.nodes += stats.nodes_visited;
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

SceneGeometry::TreeWalk SceneGeometry::walk_to(const Ray& ray, std::optional<std::size_t> sphere, std::size_t mesh,
                                               std::size_t triangle) const {
  TreeWalk walk;
  Query::Watch watch;
  // The part of the meshes that holds triangles_[i], or meshes_.size().
  const auto part_of = [&](std::uint32_t i) {
    std::uint32_t p = 0;
    while (p < meshes_.size() && !(i >= meshes_[p].first_triangle && i - meshes_[p].first_triangle < meshes_[p].triangle_count))
      ++p;
    return p;
  };
  // The primitive as the geometry holds it, and the object (a sphere, or a part of the meshes).
  std::optional<std::uint32_t> object, in_part;
  if (sphere) {
    if (*sphere >= spheres_.size()) return walk;
    watch.sphere = static_cast<std::uint32_t>(*sphere);
    object = watch.sphere;
  } else {
    for (std::uint32_t i = 0; i < triangles_.size() && !object; ++i) {
      if (triangles_[i].mesh != mesh || triangles_[i].first_index != 3 * triangle) continue;
      watch.triangle = i;
      const std::uint32_t p = part_of(i);
      if (p < meshes_.size()) {
        object = static_cast<std::uint32_t>(spheres_.size()) + p;
        in_part = i - meshes_[p].first_triangle;
      }
    }
  }
  // The nodes from a tree's root to the leaf that holds primitive `primitive`, at depth `depth` on.
  const auto path_in = [&](const Bvh& tree, std::uint32_t primitive, int mesh_index, int depth) {
    if (tree.nodes.empty()) return false;
    // Depth first, keeping the path: each entry a node and whether its second child is next.
    std::vector<std::pair<std::uint32_t, int>> stack{{0u, 0}};
    while (!stack.empty()) {
      auto& [index, visited] = stack.back();
      const BvhNode& node = tree.nodes[index];
      if (node.is_leaf()) {
        for (std::uint32_t i = node.first_index; i < node.first_index + node.primitive_count; ++i)
          if (tree.primitive_order[i] == primitive) {
            for (std::size_t k = 0; k < stack.size(); ++k)
              walk.path.push_back(
                  {mesh_index, stack[k].first, depth + static_cast<int>(k), tree.nodes[stack[k].first].bounds});
            return true;
          }
        stack.pop_back();
        continue;
      }
      if (visited == 2) {
        stack.pop_back();
        continue;
      }
      const std::uint32_t child = node.first_index + static_cast<std::uint32_t>(visited++);
      stack.push_back({child, 0});
    }
    return false;
  };
  if (object) {
    int depth = 0;
    if (!objects_bvh_.nodes.empty() && path_in(objects_bvh_, *object, -1, 0)) depth = walk.path.back().depth + 1;
    if (in_part) {
      const MeshPart& part = meshes_[*object - spheres_.size()];
      if (const Bvh* bvh = part.tree ? part.tree->binary_tree() : nullptr)
        path_in(*bvh, *in_part, static_cast<int>(mesh), depth);
    }
  }
  // The query itself, its tests watched.
  HitRecord record;
  Query query{this, &record, /*any_hit=*/false};
  query.watch = &watch;
  walk.t_hit = intersect_objects(ray, query);
  walk.tested = watch.tested;
  walk.primitive_tests = watch.tests;

  // The leaves the traversals opened (a leaf whose primitive was tested), in the order of their
  // first test, each with the closest hit the tests before it had found.
  const auto leaf_of = [](const Bvh& tree) {  // the leaf of each position of primitive_order
    std::vector<std::uint32_t> leaf(tree.primitive_order.size(), Query::Watch::kNone);
    for (std::uint32_t n = 0; n < tree.nodes.size(); ++n)
      if (tree.nodes[n].is_leaf())
        for (std::uint32_t i = tree.nodes[n].first_index;
             i < tree.nodes[n].first_index + tree.nodes[n].primitive_count && i < leaf.size(); ++i)
          leaf[i] = n;
    std::vector<std::uint32_t> by_primitive(tree.primitive_order.size(), Query::Watch::kNone);
    for (std::size_t i = 0; i < tree.primitive_order.size(); ++i)
      if (tree.primitive_order[i] < by_primitive.size()) by_primitive[tree.primitive_order[i]] = leaf[i];
    return by_primitive;
  };
  const bool object_tree = !objects_bvh_.nodes.empty();
  const std::vector<std::uint32_t> object_leaf = object_tree ? leaf_of(objects_bvh_) : std::vector<std::uint32_t>{};
  std::vector<std::vector<std::uint32_t>> part_leaf(meshes_.size());
  std::unordered_set<std::uint64_t> seen;  // the tree (0 over the objects, else 1 + the part) and leaf
  float closest = kInfinity;
  const auto open = [&](int tree, std::uint32_t leaf, int of_mesh, const Bvh& bvh) {
    if (leaf == Query::Watch::kNone) return;
    if (!seen.insert((static_cast<std::uint64_t>(tree + 1) << 32) | leaf).second) return;
    walk.leaves.push_back({of_mesh, leaf, bvh.nodes[leaf].bounds, closest});
  };
  for (const Query::Watch::Test& test : watch.order) {
    std::uint32_t tested_object = test.index;
    if (!test.is_sphere) {
      const std::uint32_t p = part_of(test.index);
      if (p == meshes_.size()) continue;
      tested_object = static_cast<std::uint32_t>(spheres_.size()) + p;
      if (object_tree && tested_object < object_leaf.size()) open(-1, object_leaf[tested_object], -1, objects_bvh_);
      if (const Bvh* bvh = meshes_[p].tree ? meshes_[p].tree->binary_tree() : nullptr) {
        if (part_leaf[p].empty()) part_leaf[p] = leaf_of(*bvh);
        const std::uint32_t local = test.index - meshes_[p].first_triangle;
        if (local < part_leaf[p].size())
          open(static_cast<int>(p), part_leaf[p][local], static_cast<int>(triangles_[test.index].mesh), *bvh);
      }
    } else if (object_tree && tested_object < object_leaf.size()) {
      open(-1, object_leaf[tested_object], -1, objects_bvh_);
    }
    if (test.t_max > closest + 1e-4f * std::max(1.0f, std::fabs(closest))) {
      if (walk.tests_beyond_a_hit++ == 0) walk.first_test_beyond_a_hit = {test.t_max, closest};
    }
    if (test.t && *test.t < closest) closest = *test.t;
  }
  walk.leaves_cut = watch.dropped;
  return walk;
}

}  // namespace raylab
