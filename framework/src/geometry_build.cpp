// SceneGeometry, part 1 of 4: building. The scene's triangles in one array (per mesh, in
// its tree's leaf order), each mesh's stage tree (mesh_trees.h: the median, SAH, 4-wide or
// KD-tree, by StageTree) and the tree over the objects (the student's build_bvh or
// build_bvh_sah), each checked before use, a probe that finds out at once whether the stages they
// need are stubs, and for StageTree::Best the choice of the best tree whose answers are those of
// testing every primitive. The words of each tree (stage_tree_name, stage_tree_facts).
// (geometry_bvh_adapters.cpp: queries through the trees; geometry_brute_force.cpp: without
// them; geometry.cpp: the public queries and the hit details.)
#include "raylab/geometry.h"

#include "mesh_trees.h"
#include "tree_answers.h"

#include "raylab/error.h"
#include "raylab/random.h"
#include "raylab/stages/02_sphere.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

namespace {

Bounds3 sphere_bounds(const Sphere& sphere) {
  const glm::vec3 reach(std::fabs(sphere.radius));
  return {sphere.center - reach, sphere.center + reach};
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
  // A program's own tree (TracingFunctions::own_tree) takes every triangle of the scene at once:
  // no tree per mesh under a tree over the objects, and no tests one by one for the small meshes
  // (a wall of two triangles) that a tree per mesh would not pay for. Only with stage 03's
  // Moller-Trumbore test, which the own tree tests itself.
  const bool own_tree = tracing.own_tree && !tracing.replaces_primitive_tests() &&
                        triangle_test == TriangleTest::MollerTrumbore && acceleration != Acceleration::BruteForce;
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    if (meshes_.empty() || !own_tree) {
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
  if (own_tree && !triangles_.empty()) {
    std::vector<glm::vec3> corners;
    corners.reserve(3 * triangles_.size());
    for (const Triangle& triangle : triangles_) corners.insert(corners.end(), {triangle.p0, triangle.p1, triangle.p2});
    const std::shared_ptr<const TriangleTree> tree = tracing.own_tree(corners);
    if (!tree) throw std::logic_error("TracingFunctions::own_tree built no tree (raylab/accelerator.h: never nullptr)");
    meshes_.front().own_tree = tree;
    tree_choice_.own_tree = tree->name();
    if (spheres_.empty()) only_tree_ = tree.get();
  }
  if (acceleration == Acceleration::BvhAlways) brute_force_limit_ = 0;
  if (tracing.replaces_primitive_tests() && !tracing.keep_trees) acceleration = Acceleration::BruteForce;
  // With an own tree, the stage trees are only the tree over the objects (spheres and the own
  // tree's triangles): the median one, tried on nothing else.
  const StageTree tree = own_tree && tracing.tree != StageTree::None ? StageTree::Median : tracing.tree;
  if (acceleration != Acceleration::BruteForce && tree != StageTree::None) {
    if (tree == StageTree::Best)
      build_best_trees(triangle_test, tracing);
    else
      build_bvhs(tree);
  }
}

void SceneGeometry::build_bvhs(StageTree tree) {
  tree_choice_.used = tree;
  BinaryTreeBuild binary(tree);  // (Wide: over the SAH tree where stage 05b is written, else the median one)
  try {
    for (MeshPart& mesh : meshes_) {
      if (mesh.triangle_count <= brute_force_limit_ || mesh.own_tree) continue;
      Triangle* first = triangles_.data() + mesh.first_triangle;
      std::vector<Bounds3> boxes;
      boxes.reserve(mesh.triangle_count);
      for (std::uint32_t i = 0; i < mesh.triangle_count; ++i)
        boxes.push_back(triangle_bounds(first[i].p0, first[i].p1, first[i].p2));
      const bool one_mesh = first->mesh == first[mesh.triangle_count - 1].mesh;
      const std::string name = one_mesh ? scene_.meshes[first->mesh].name : "the scene's triangles";
      mesh.tree = build_mesh_tree(binary, boxes, name, [&](const std::vector<std::uint32_t>& leaf_order) {
        std::vector<Triangle> reordered;
        reordered.reserve(mesh.triangle_count);
        for (const std::uint32_t i : leaf_order) reordered.push_back(first[i]);
        std::copy(reordered.begin(), reordered.end(), first);
      });
    }
    const std::size_t object_count = spheres_.size() + meshes_.size();
    if (object_count > brute_force_limit_) {
      std::vector<Bounds3> boxes;
      boxes.reserve(object_count);
      for (const Sphere& sphere : spheres_) boxes.push_back(sphere_bounds(sphere));
      for (const MeshPart& mesh : meshes_) boxes.push_back(mesh.bounds);
      objects_bvh_ = binary.build(boxes, std::nullopt);
    }
    // A traversal needs the box tests and its stage's traversal: find out now, with one query
    // on the tree over the objects and one on a mesh's tree (every mesh's is of one kind), whether
    // they are still stubs, rather than in the middle of the render.
    const MeshTree* mesh_tree = nullptr;
    for (const MeshPart& mesh : meshes_)
      if (!mesh_tree && mesh.tree) mesh_tree = mesh.tree.get();
    if (!objects_bvh_.nodes.empty()) probe_binary_tree(objects_bvh_);
    if (mesh_tree) mesh_tree->probe();
    const bool binary_tree = !objects_bvh_.nodes.empty() || (mesh_tree && mesh_tree->binary_tree());
    if (!binary_tree && !meshes_.empty() && meshes_.front().own_tree) {  // only the own tree: no stage tree needed
      tree_choice_.used = StageTree::None;
    } else if (tree == StageTree::KdTree && !mesh_tree) {
      tree_choice_.used = binary_tree ? StageTree::Median : StageTree::None;
      tree_choice_.small_sets_only = !binary_tree;
      if (binary_tree)
        tree_choice_.passed_over.push_back("kdtree: no mesh has more than " + std::to_string(brute_force_limit_) +
                                           " triangles, so none has a KD-tree");
    } else if (!binary_tree && !mesh_tree) {  // no set of primitives large enough for a tree
      tree_choice_.used = StageTree::None;
      tree_choice_.small_sets_only = true;
    } else if (tree == StageTree::Wide && !mesh_tree) {
      tree_choice_.used = binary.sah ? StageTree::Sah : StageTree::Median;
      tree_choice_.passed_over.push_back("wide: no mesh has more than " + std::to_string(brute_force_limit_) +
                                         " triangles, so none has a 4-wide tree");
    }
  } catch (const NotImplemented& error) {
    drop_trees();
    fallback_stage_ = error.stage_id();
    tree_choice_.stub_stage = error.stage_id();
  }
}

void SceneGeometry::drop_trees() {
  for (MeshPart& mesh : meshes_) mesh.tree.reset();
  objects_bvh_ = Bvh();
  tree_choice_.used = StageTree::None;
}

void SceneGeometry::build_best_trees(TriangleTest triangle_test, const TracingFunctions& tracing) {
  TracingFunctions without_trees = tracing;
  without_trees.tree = StageTree::None;
  std::optional<SceneGeometry> every_primitive;  // the answers to match, made when first needed
  // Each candidate starts from the triangles in the scene's order (a build stores them in its
  // leaf order), so that the one chosen is the tree --accel would build.
  const std::vector<Triangle> scene_order = triangles_;
  // A stub of another stage (02, 03) is no reason to pass a tree over: the render needs it anyway.
  // The stages of the trees: the box test and quickselect, which the binary trees need, and each
  // tree's own.
  const auto tree_stage = [](const std::string& stage) {
    if (stage == "04_box" || stage == "04b_quickselect") return true;
    for (const StageTree tree : kStageBuiltTrees)
      if (stage == stage_tree_facts(tree).stage) return true;
    return false;
  };
  for (const StageTree candidate : {StageTree::Wide, StageTree::Sah, StageTree::KdTree, StageTree::Median}) {
    const std::string name = stage_tree_name(candidate);
    const auto pass_over = [&](const std::string& why) {
      tree_choice_.passed_over.push_back(name + ": " + why);
      drop_trees();
      triangles_ = scene_order;
    };
    fallback_stage_.clear();
    tree_choice_.stub_stage.clear();
    tree_choice_.small_sets_only = false;
    try {
      build_bvhs(candidate);
      if (tree_choice_.small_sets_only) return;  // no set large enough for a tree: every choice is the same
      if (tree_choice_.used == StageTree::None) {  // a stage it needs is a stub
        if (candidate == StageTree::Median) {  // testing every primitive, and saying why
          tree_choice_.passed_over.clear();  // the better trees need this one's stages too
          return;
        }
        pass_over("stage " + fallback_stage_ + " is not written yet");
        continue;
      }
      if (!every_primitive) every_primitive.emplace(scene_, Acceleration::BruteForce, triangle_test, without_trees);
      if (const std::optional<std::string> difference = differs_from(*every_primitive)) {
        pass_over(*difference);
        continue;
      }
      return;
    } catch (const NotImplemented& error) {
      if (!tree_stage(error.stage_id())) throw;
      pass_over("stage " + error.stage_id() + " is not written yet");
    } catch (const std::exception& error) {
      pass_over(error.what());
    }
  }
  fallback_stage_.clear();  // none would do: every primitive, and tree_choice_ says why
}

std::optional<std::string> SceneGeometry::differs_from(const SceneGeometry& every_primitive) const {
  Bounds3 bounds;
  for (const Sphere& sphere : spheres_) bounds.extend(sphere_bounds(sphere));
  for (const MeshPart& mesh : meshes_) bounds.extend(mesh.bounds);
  if (!(bounds.min.x <= bounds.max.x)) return std::nullopt;
  // Rays from the camera and from points around the scene to points in it: as many as keep the
  // testing of every primitive to about 4 million tests.
  const std::size_t primitives = std::max<std::size_t>(1, spheres_.size() + triangles_.size());
  const std::size_t ray_count = std::clamp<std::size_t>(4000000 / primitives, 16, 256);
  Pcg32 random(mix_bits(primitives));  // the same rays for the same scene
  const glm::vec3 size = bounds.max - bounds.min;
  const auto point_in = [&](float grow) {
    const float x = random.next_float(), y = random.next_float(), z = random.next_float();
    return bounds.min - grow * size + (1.0f + 2.0f * grow) * glm::vec3(x, y, z) * size;
  };
  const auto t_text = [](const std::optional<SurfaceHit>& hit) {
    return hit ? "a hit at t = " + std::to_string(hit->t_hit) : std::string("no hit");
  };
  for (std::size_t i = 0; i < ray_count; ++i) {
    const glm::vec3 origin = i % 2 == 0 ? scene_.camera.position : point_in(0.1f);
    const glm::vec3 direction = point_in(0.0f) - origin;
    if (!(glm::dot(direction, direction) > 0.0f)) continue;
    const Ray ray = make_ray(origin, direction);
    const std::optional<SurfaceHit> yours = intersect(ray), expected = every_primitive.intersect(ray);
    if (!same_closest_t(yours ? std::optional<float>(yours->t_hit) : std::nullopt,
                        expected ? std::optional<float>(expected->t_hit) : std::nullopt))
      return "its closest hit differs from testing every primitive on ray " + std::to_string(i) + " of " +
             std::to_string(ray_count) + " through the scene (" + t_text(yours) + ", not " + t_text(expected) + ")";
    if (occluded(ray) != every_primitive.occluded(ray))
      return "its any-hit query differs from testing every primitive on ray " + std::to_string(i) + " of " +
             std::to_string(ray_count) + " through the scene";
  }
  return std::nullopt;
}

std::size_t SceneGeometry::bvh_count() const {
  std::size_t count = objects_bvh_.nodes.empty() ? 0 : 1;
  for (const MeshPart& mesh : meshes_) count += mesh.has_tree() ? 1 : 0;
  return count;
}

std::size_t SceneGeometry::tree_bytes() const {
  std::size_t bytes = objects_bvh_.nodes.size() * sizeof(BvhNode) + objects_bvh_.primitive_order.size() * 4;
  for (const MeshPart& mesh : meshes_) bytes += mesh.tree ? mesh.tree->bytes() : 0;
  return bytes;
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
    if (const Bvh* bvh = meshes_[mesh].tree ? meshes_[mesh].tree->binary_tree() : nullptr)
      add_tree(*bvh, depth, [](const BvhNode&, int) {});
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

const char* stage_tree_name(StageTree tree) {
  switch (tree) {
    case StageTree::Median: return "median";
    case StageTree::Sah: return "sah";
    case StageTree::Wide: return "wide";
    case StageTree::KdTree: return "kdtree";
    case StageTree::None: return "none";
    case StageTree::Best: return "best";
  }
  return "?";
}

namespace {
constexpr StageTree kEveryStageTree[] = {StageTree::Best, StageTree::Median, StageTree::Sah, StageTree::Wide,
                                         StageTree::KdTree, StageTree::None};
}

std::optional<StageTree> stage_tree_named(const std::string& name) {
  for (const StageTree tree : kEveryStageTree)
    if (name == stage_tree_name(tree)) return tree;
  return std::nullopt;
}

std::string stage_tree_words() {
  std::string words;
  for (const StageTree tree : kEveryStageTree) words += (words.empty() ? "" : ", ") + std::string(stage_tree_name(tree));
  return words;
}

std::vector<std::string> stage_tree_word_list() {
  std::vector<std::string> words;
  for (const StageTree tree : kEveryStageTree) words.emplace_back(stage_tree_name(tree));
  return words;
}

const StageTreeFacts& stage_tree_facts(StageTree tree) {
  static const StageTreeFacts median{"median BVH", "05_bvh", "build_bvh", "intersect_bvh"};
  static const StageTreeFacts sah{"SAH BVH", "05b_bvh_sah", "build_bvh_sah", "intersect_bvh"};
  static const StageTreeFacts wide{"4-wide BVH", "05c_wide_bvh", "collapse_bvh4", "intersect_bvh4"};
  static const StageTreeFacts kdtree{"KD-tree", "05d_kdtree", "build_kdtree", "intersect_kdtree"};
  switch (tree) {
    case StageTree::Median: return median;
    case StageTree::Sah: return sah;
    case StageTree::Wide: return wide;
    case StageTree::KdTree: return kdtree;
    default: break;
  }
  throw std::invalid_argument(std::string("stage_tree_facts: no stage builds the tree '") + stage_tree_name(tree) + "'");
}

}  // namespace raylab
