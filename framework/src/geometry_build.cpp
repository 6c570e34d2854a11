// SceneGeometry, part 1 of 4: building. The scene's triangles in one array (per mesh, in
// its BVH's leaf order), the per-mesh and top-level trees from the student's build_bvh, each
// checked before use, and a probe that finds out at once whether stages 04 and 05 are stubs.
// (geometry_bvh_adapters.cpp: queries through the trees; geometry_brute_force.cpp: without
// them; geometry.cpp: the public queries and the hit details.)
#include "raylab/geometry.h"

#include "raylab/bvh_tools.h"
#include "raylab/error.h"
#include "raylab/stages/02_sphere.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"
#include "raylab/stages/05c_wide_bvh.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

namespace {

// A student's build_bvh may return a tree that would send the traversal out of its arrays:
// stop with the broken rule in words rather than crash (or render garbage) later.
// `mesh`: the mesh's name, or nullopt for the tree over the scene's objects.
void check_tree(const Bvh& bvh, const std::vector<Bounds3>& boxes, const std::optional<std::string>& mesh) {
  if (const std::optional<BvhViolation> broken = find_bvh_violation(bvh, boxes, SceneGeometry::kBvhLeafSize))
    throw BrokenBvh(*broken, boxes.size(), mesh);
}

Bounds3 triangle_bounds(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  Bounds3 box;
  box.extend(p0);
  box.extend(p1);
  box.extend(p2);
  return box;
}

}  // namespace

SceneGeometry::SceneGeometry(const Scene& scene, Acceleration acceleration, TriangleTest triangle_test,
                             const TracingFunctions& tracing)
    : scene_(scene), spheres_(scene.spheres),
      intersect_triangle_(tracing.triangle                             ? tracing.triangle
                          : triangle_test == TriangleTest::Watertight ? intersect_ray_triangle_watertight
                                                                      : intersect_ray_triangle),
      intersect_sphere_(tracing.sphere ? tracing.sphere : intersect_ray_sphere) {
  // The reference's own stages (raylab-reference, bench/) trace every triangle of the scene
  // through one SAH tree (stage 05b), 8 wide (TracingFunctions::reference_tree) or else 4 wide
  // (stage 05c): no tree per mesh under a tree over the objects, and no calls for the small
  // meshes (a wall of two triangles) that a per-mesh tree would not pay for. The same closest
  // hits; a student's program keeps a median tree per mesh, as the header says.
  reference_trees_ = tracing.reference_stages && !tracing.replaces_primitive_tests();
  if (reference_trees_) reference_tree_functions_ = tracing.reference_tree;
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    if (meshes_.empty() || !reference_trees_) {
      meshes_.emplace_back();
      meshes_.back().first_triangle = static_cast<std::uint32_t>(triangles_.size());
    }
    MeshPart& part = meshes_.back();
    for (std::uint32_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const Triangle triangle{mesh.positions[mesh.indices[i]], mesh.positions[mesh.indices[i + 1]],
                              mesh.positions[mesh.indices[i + 2]], m, i};
      part.bounds.extend(triangle_bounds(triangle.p0, triangle.p1, triangle.p2));
      triangles_.push_back(triangle);
    }
    part.triangle_count = static_cast<std::uint32_t>(triangles_.size()) - part.first_triangle;
  }
  if (acceleration == Acceleration::BvhAlways) brute_force_limit_ = 0;
  if (tracing.replaces_primitive_tests() && !tracing.keep_trees) acceleration = Acceleration::BruteForce;
  if (acceleration != Acceleration::BruteForce) build_bvhs();
  only_one_tree_ = reference_trees_ && spheres_.empty() && meshes_.size() == 1 && !meshes_.front().bvh.nodes.empty();
  // bvh_count() is 0 when testing every primitive (brute force, or stage 05 a stub).
  hand_triangles_to_traversal_ = reference_trees_ && triangle_test == TriangleTest::MollerTrumbore && bvh_count() > 0;
  if (hand_triangles_to_traversal_) {
    triangle_edges_.reserve(triangles_.size());
    for (const Triangle& triangle : triangles_)
      triangle_edges_.push_back(TriangleEdges::of(triangle.p0, triangle.p1, triangle.p2));
    // The reference's trees also get the triangles as columns, for its four-at-a-time leaf test.
    // (Both trees keep the binary tree's primitive_order: the identity, in leaf order.)
    for (MeshPart& mesh : meshes_)
      if (!mesh.wide.nodes.empty() || mesh.reference_tree)
        mesh.columns = triangle_columns(triangle_edges_.data() + mesh.first_triangle, mesh.bvh.primitive_order);
  }
  straight_into_the_one_tree_ =
      only_one_tree_ && hand_triangles_to_traversal_ && !meshes_.front().columns.empty() &&
      (!meshes_.front().reference_tree ||
       (reference_tree_functions_->closest_triangle && reference_tree_functions_->any_triangle));
  if (straight_into_the_one_tree_) {
    the_one_reference_tree_ = meshes_.front().reference_tree.get();
    the_one_tree_columns_ = TriangleColumns::of(meshes_.front().columns);
  }
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
      mesh.bvh = reference_trees_ ? build_bvh_sah(boxes, kBvhLeafSize) : build_bvh(boxes, kBvhLeafSize);
      const bool one_mesh = first->mesh == first[mesh.triangle_count - 1].mesh;
      check_tree(mesh.bvh, boxes, one_mesh ? scene_.meshes[first->mesh].name : "the scene's triangles");
      // Store the triangles in leaf order, so that a leaf's triangles are adjacent in memory;
      // the BVH's primitive_order then becomes the identity.
      std::vector<Triangle> reordered;
      reordered.reserve(mesh.triangle_count);
      for (std::uint32_t i = 0; i < mesh.triangle_count; ++i) {
        reordered.push_back(first[mesh.bvh.primitive_order[i]]);
        mesh.bvh.primitive_order[i] = i;
      }
      std::copy(reordered.begin(), reordered.end(), first);
      if (reference_trees_) {
        if (reference_tree_functions_) mesh.reference_tree = reference_tree_functions_->build(mesh.bvh);
        if (!mesh.reference_tree) mesh.wide = collapse_bvh4(mesh.bvh);
      }
    }
    const std::size_t object_count = spheres_.size() + meshes_.size();
    if (object_count > brute_force_limit_) {
      std::vector<Bounds3> boxes;
      boxes.reserve(object_count);
      for (const Sphere& sphere : spheres_)
        boxes.emplace_back(sphere.center - glm::vec3(sphere.radius), sphere.center + glm::vec3(sphere.radius));
      for (const MeshPart& mesh : meshes_) boxes.push_back(mesh.bounds);
      objects_bvh_ = build_bvh(boxes, kBvhLeafSize);
      check_tree(objects_bvh_, boxes, std::nullopt);
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
    for (MeshPart& mesh : meshes_) {
      mesh.bvh = Bvh();
      mesh.wide = Bvh4();
      mesh.reference_tree.reset();
    }
    objects_bvh_ = Bvh();
    fallback_stage_ = error.stage_id();
  }
}

std::size_t SceneGeometry::bvh_count() const {
  std::size_t count = objects_bvh_.nodes.empty() ? 0 : 1;
  for (const MeshPart& mesh : meshes_) count += mesh.bvh.nodes.empty() ? 0 : 1;
  return count;
}

std::vector<std::vector<Bounds3>> SceneGeometry::tree_boxes_by_level() const {
  std::vector<std::vector<Bounds3>> levels;
  // Adds the boxes of `tree`'s nodes, its root at `depth`; calls leaf(node, depth) at each leaf.
  const auto add_tree = [&](const Bvh& tree, int root_depth, const auto& leaf) {
    if (tree.nodes.empty()) return;
    std::vector<std::pair<std::uint32_t, int>> stack{{0u, root_depth}};
    while (!stack.empty()) {
      const auto [index, depth] = stack.back();
      stack.pop_back();
      const BvhNode& node = tree.nodes[index];
      if (levels.size() <= static_cast<std::size_t>(depth)) levels.resize(static_cast<std::size_t>(depth) + 1);
      levels[static_cast<std::size_t>(depth)].push_back(node.bounds);
      if (node.is_leaf()) {
        leaf(node, depth);
      } else {
        stack.push_back({node.first_index + 1, depth + 1});
        stack.push_back({node.first_index, depth + 1});
      }
    }
  };
  const auto mesh_tree_at = [&](std::size_t mesh, int depth) {
    add_tree(meshes_[mesh].bvh, depth, [](const BvhNode&, int) {});
  };
  if (objects_bvh_.nodes.empty()) {
    for (std::size_t m = 0; m < meshes_.size(); ++m) mesh_tree_at(m, 0);
  } else {
    // A mesh's tree hangs below the leaf of the objects' tree that holds the mesh.
    add_tree(objects_bvh_, 0, [&](const BvhNode& leaf, int depth) {
      for (std::uint32_t i = leaf.first_index; i < leaf.first_index + leaf.primitive_count; ++i) {
        const std::size_t object = objects_bvh_.primitive_order[i];
        if (object >= spheres_.size()) mesh_tree_at(object - spheres_.size(), depth + 1);
      }
    });
  }
  return levels;
}

}  // namespace raylab
