// The scene's geometry as the renderer sees it: closest-hit and any-hit queries over all
// spheres and triangles, calling the stage functions (02_sphere, 03_triangle) for each test.
//
// Acceleration (stages 04_box, 05_bvh): every mesh of more than a few triangles gets its own
// BVH over its triangles, and a scene of more than a few objects (spheres and meshes) a
// top-level BVH over the objects' boxes; smaller sets are tested one by one. Which stage trees
// (TracingFunctions::tree): the median build, the SAH build (05b), the mesh trees collapsed to 4
// wide (05c), a KD-tree per mesh (05d), or the best of those the student wrote (raylab render
// --accel). A program may
// instead hand in a tree of its own over every triangle of the scene (TracingFunctions::own_tree,
// raylab/accelerator.h), as the programs that link solutions/ do. If build_bvh,
// intersect_bvh or intersect_ray_box is still a stub (throws NotImplemented), the geometry
// tests every primitive and says so once per process on stderr, at the first query:
// "raylab: stage 05_bvh not implemented yet: testing every primitive (slow)": a student who has not reached stage 5 can still render.
// When the render will take more than 10 s, the same line says how long at least (timed on a
// sample of the student's own tests) and suggests a smaller --width/--height.
//
// In framework/src/: geometry_build.cpp (the triangle array, the trees, the stub probe),
// mesh_trees.cpp (each mesh's stage tree behind one interface, MeshTree, and its checks),
// geometry_bvh_adapters.cpp (the primitive tests a traversal calls, and the check of what it
// returned), geometry_brute_force.cpp (every object in turn, and the slow-render estimate),
// geometry.cpp (the public queries, and the hit details shading needs).
#pragma once

#include "raylab/accelerator.h"
#include "raylab/camera.h"
#include "raylab/ray.h"
#include "raylab/scene.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/stages/03b_watertight.h"
#include "raylab/stages/05_bvh.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

class MeshTree;  // one mesh's stage tree (framework/src/mesh_trees.h)

// Everything shading needs about the closest hit, filled in after t_hit is known.
struct SurfaceHit {
  float t_hit = 0.0f;
  glm::vec3 point{0.0f};
  glm::vec3 point_error{0.0f};       // a bound on |computed point - true point| per axis
  glm::vec3 geometric_normal{0.0f};  // unit length; by winding for triangles, Sphere::faces_inward for spheres
  glm::vec2 texcoord{0.0f};
  bool has_texcoord = false;
  std::uint32_t material = 0;
};

// How SceneGeometry finds hits.
enum class Acceleration {
  Bvh,         // BVHs where they pay (the default), or every primitive if stage 5 is a stub
  BvhAlways,   // BVHs even for a handful of primitives (to measure what skipping them saves)
  BruteForce,  // test every primitive (an oracle for tests, a baseline for bench/)
};

// Which of the stage trees a program traces (raylab render --accel): each mesh's tree and the
// tree over the objects.
enum class StageTree {
  Median,  // stage 05: build_bvh, traversed by intersect_bvh
  Sah,     // stage 05b: build_bvh_sah, traversed by intersect_bvh
  Wide,    // stage 05c: the SAH tree (the median one while 05b is a stub) collapsed by
           // collapse_bvh4, each mesh's traversed by intersect_bvh4
  KdTree,  // stage 05d: build_kdtree over each mesh's triangles, traversed by intersect_kdtree (the
           // tree over the objects is the median one)
  None,    // no tree: every primitive tested
  Best,    // Wide, Sah, KdTree or Median: the first whose stages are written and whose answers are
           // those of testing every primitive, on a sample of rays (SceneGeometry::tree_choice says which)
};
// The --accel word of a tree ("median", "sah", "wide", "kdtree", "none", "best"), and back (nullopt:
// none); all the words, for a usage message ("best, median, sah, wide, kdtree, none").
const char* stage_tree_name(StageTree tree);
std::optional<StageTree> stage_tree_named(const std::string& name);
std::string stage_tree_words();
std::vector<std::string> stage_tree_word_list();
// What the render's first line, raylab trace and raylab bench say of a tree that a stage builds.
struct StageTreeFacts {
  const char* what;       // "median BVH"
  const char* stage;      // the stage it is written in: "05_bvh"
  const char* build;      // the function that makes it: "build_bvh" ("collapse_bvh4" for the 4-wide tree)
  const char* traversal;  // the function that walks it: "intersect_bvh"
};
// Of Median, Sah, Wide and KdTree (std::invalid_argument for None and Best).
const StageTreeFacts& stage_tree_facts(StageTree tree);
// The trees the stages build, in teaching order (raylab bench's rows).
constexpr StageTree kStageBuiltTrees[] = {StageTree::Median, StageTree::Sah, StageTree::Wide, StageTree::KdTree};

// Which ray-triangle test every triangle query uses.
enum class TriangleTest {
  MollerTrumbore,  // stage 03_triangle, intersect_ray_triangle (the default)
  Watertight,      // bonus stage 06_robustness: no ray slips through a closed mesh's shared edges
};

// The functions that trace a render's rays. Each left nullptr is the stage's own: stage 01's
// generate_camera_ray, stage 02's intersect_ray_sphere, stage 03's intersect_ray_triangle (or
// 03b's, by TriangleTest), from whichever stage library the program links. The autograder's
// Monte Carlo stages (08, 09) give the grader's own (autograder/suites/grader_geometry.h), so
// that a mistake in stages 01-05 costs points only in its own stage. A geometry given its own
// sphere or triangle test tests every primitive (the trees of stages 04-05 are stage code too),
// unless keep_trees says to trace them (the picture of stage 05's image test).
struct TracingFunctions {
  Ray (*camera_ray)(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) = nullptr;
  std::optional<float> (*sphere)(const Ray& ray, const glm::vec3& center, float radius) = nullptr;
  std::optional<TriangleHit> (*triangle)(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                         const glm::vec3& p2) = nullptr;
  // A program's own tree over every triangle of the scene (raylab/accelerator.h), traced
  // instead of the stage trees over the meshes when the triangles are tested with stage 03's
  // Moller-Trumbore and no test above is given: the tree tests them itself, with the same
  // answers (the triangle found may differ on a tie). The spheres stay as they are, under a
  // median tree over the objects (the own tree's triangles one of them) where there are more than
  // a few; `tree` says only whether there is one (StageTree::None: no tree). The programs that link solutions/ give the fastest tree of the
  // solutions (solutions/05c_wide_bvh/fast_tree.h); a student's program and the graders give none.
  TriangleTreeBuilder own_tree = nullptr;
  // With a sphere or triangle test given above: still trace the scene through the stage-05 trees
  // (build_bvh, intersect_bvh and stage 04's box test) rather than test every primitive.
  bool keep_trees = false;
  // Which stage trees.
  StageTree tree = StageTree::Median;
  bool replaces_primitive_tests() const { return sphere != nullptr || triangle != nullptr; }
};

class SceneGeometry {
 public:
  // The scene must outlive the geometry (its meshes' texture coordinates are read at hits).
  explicit SceneGeometry(const Scene& scene, Acceleration acceleration = Acceleration::Bvh,
                         TriangleTest triangle_test = TriangleTest::MollerTrumbore,
                         const TracingFunctions& tracing = {});
  // Not copied: it keeps pointers into its own arrays (a move keeps them valid).
  SceneGeometry(const SceneGeometry&) = delete;
  SceneGeometry& operator=(const SceneGeometry&) = delete;
  SceneGeometry(SceneGeometry&&) = default;

  // The closest hit in (ray.t_min, ray.t_max), or nullopt.
  std::optional<SurfaceHit> intersect(const Ray& ray) const;
  // Whether anything is hit in (ray.t_min, ray.t_max): stops at the first hit found.
  bool occluded(const Ray& ray) const;

  // The tree it traces (never StageTree::Best; None when it tests every primitive, also while
  // stage 04 or 05 is a stub, or when a program's own tree takes every triangle and no tree over
  // the objects is needed), and for StageTree::Best, why each better one was passed over (in
  // words, "stage 05c_wide_bvh: collapse_bvh4 is not written yet"). `own_tree`: the name of the
  // program's own tree over the triangles (TracingFunctions::own_tree), or "".
  struct TreeChoice {
    StageTree used = StageTree::None;
    std::string own_tree;
    std::vector<std::string> passed_over;
    std::string stub_stage;  // the stage whose stub left no tree ("05c_wide_bvh"), or ""
    bool small_sets_only = false;  // used None as no set of primitives is large enough for a tree
  };
  const TreeChoice& tree_choice() const { return tree_choice_; }
  // The trees' work on this thread since the last call: the nodes whose boxes the traversals
  // tested and the primitive tests they asked for (stats of intersect_bvh and intersect_bvh4),
  // and the primitives tested one by one. A program's own tree (TracingFunctions::own_tree)
  // counts nothing.
  struct Work {
    std::uint64_t nodes = 0, primitives = 0;
  };
  static Work take_thread_work();

  std::size_t sphere_count() const { return spheres_.size(); }
  std::size_t triangle_count() const { return triangles_.size(); }
  // The number of BVHs in use (per mesh and top level); 0 when every primitive is tested.
  std::size_t bvh_count() const;
  // The memory the stage trees in use take: nodes, primitive orders and leaf lists, in bytes (0 for
  // a program's own tree, which keeps its own).
  std::size_t tree_bytes() const;
  // The boxes of those trees' nodes by depth (`raylab view` draws one level at a time): the tree
  // over the objects from depth 0, each mesh's tree from the depth below the leaf that holds its
  // mesh (from 0 when there is no tree over the objects). Empty when no tree is in use.
  std::vector<std::vector<Bounds3>> tree_boxes_by_level() const;

  // How the trees lead a ray to one primitive (`raylab trace`): the nodes from the root down to
  // the leaf that holds it (the tree over the objects, then its mesh's tree), which primitive
  // tests intersect(ray) called, and the leaves it opened. The primitive: `sphere`, an index into scene.spheres, or
  // triangle `triangle` of scene.meshes[mesh] when `sphere` is nullopt.
  struct TreeNodeOnPath {
    int mesh = -1;  // -1: a node of the tree over the objects; else the index of the mesh whose tree
    std::uint32_t node = 0;
    int depth = 0;  // as tree_boxes_by_level counts it
    Bounds3 box;
  };
  // A leaf a traversal opened (one of its primitives was tested), and the closest hit the tests
  // made before it had found (kInfinity: none).
  struct LeafOpened {
    int mesh = -1;  // as TreeNodeOnPath's
    std::uint32_t node = 0;
    Bounds3 box;
    float closest_before = kInfinity;
  };
  struct TreeWalk {
    std::vector<TreeNodeOnPath> path;  // root first; empty when no tree holds the primitive
    bool tested = false;               // intersect(ray) called the primitive's test
    std::uint64_t primitive_tests = 0;  // every primitive test it called
    std::optional<float> t_hit;        // what it found
    std::vector<LeafOpened> leaves;    // in the order the traversals opened them
    bool leaves_cut = false;           // more tests than were kept: only the first leaves
    // The tests given a ray whose t_max lay beyond a hit already found (the traversal did not
    // lower t_max), and the first one's t_max and that hit's t.
    std::uint64_t tests_beyond_a_hit = 0;
    std::pair<float, float> first_test_beyond_a_hit{0.0f, 0.0f};
  };
  TreeWalk walk_to(const Ray& ray, std::optional<std::size_t> sphere, std::size_t mesh, std::size_t triangle) const;

  // Over the objects: spheres first, then meshes. Top-level BVHs are built from more than
  // this many objects, per-mesh BVHs from more than this many triangles; leaves hold at most
  // kBvhLeafSize primitives.
  static constexpr std::size_t kBruteForceLimit = 4;
  static constexpr int kBvhLeafSize = 4;

 private:
  struct Triangle {
    Triangle(const glm::vec3& p0_, const glm::vec3& p1_, const glm::vec3& p2_, std::uint32_t mesh_,
             std::uint32_t first_index_);
    glm::vec3 p0, p1, p2;
    std::uint32_t mesh;
    std::uint32_t first_index;  // into the mesh's indices: its 3 vertices start here
    // Its unit normal, cross(p1 - p0, p2 - p0) normalised, once for all of its hits; has_area
    // false (and normal zero) when the triangle is degenerate and has none.
    glm::vec3 normal;
    bool has_area;
  };
  enum class Kind : std::uint8_t { None, Sphere, Triangle };
  // One mesh's triangles (with own_tree, every mesh's): triangles_[first_triangle ..
  // first_triangle + triangle_count), in its BVH's leaf order when it has one (then the BVH's
  // primitive_order is the identity).
  struct MeshPart {
    std::uint32_t first_triangle = 0;
    std::uint32_t triangle_count = 0;
    Bounds3 bounds;
    // The stage tree over these triangles (framework/src/mesh_trees.h: median, SAH, 4-wide or
    // KD-tree, by TracingFunctions::tree), or nullptr: test every triangle.
    std::shared_ptr<const MeshTree> tree;
    // The program's own tree over these triangles (TracingFunctions::own_tree), traced instead of
    // a stage tree (then nullptr); its triangle indices count from first_triangle.
    std::shared_ptr<const TriangleTree> own_tree;
    // Whether a tree finds its hits (intersect_mesh), rather than a test of each triangle.
    bool has_tree() const { return tree || own_tree; }
  };
  // The closest hit a query's primitive tests have reported so far (by the framework's own
  // comparison of t, whatever order a traversal calls the tests in), and its details.
  struct HitRecord {
    Kind kind = Kind::None;
    std::uint32_t index = 0;  // into spheres_ or triangles_
    float t_hit = kInfinity;  // kInfinity while kind == Kind::None
    TriangleHit triangle_hit;

    void set_sphere(std::uint32_t sphere, float t) {
      kind = Kind::Sphere;
      index = sphere;
      t_hit = t;
    }
    void set_triangle(std::uint32_t triangle, const TriangleHit& hit) {
      kind = Kind::Triangle;
      index = triangle;
      t_hit = hit.t_hit;
      triangle_hit = hit;
    }
  };
  struct Query;

  // The trees of kind `tree` (not Best): every large mesh's (MeshPart::tree) and the one over the objects.
  void build_bvhs(StageTree tree);
  // StageTree::Best: tries Wide, Sah, KdTree and Median in turn (tree_choice_ says why not the others).
  void build_best_trees(TriangleTest triangle_test, const TracingFunctions& tracing);
  // Whether the trees give the answers of testing every primitive (`every_primitive`, a geometry
  // without trees) on a sample of rays through the scene's bounds; else the first that differs, in
  // words.
  std::optional<std::string> differs_from(const SceneGeometry& every_primitive) const;
  void drop_trees();
  std::string brute_force_estimate(const Ray& sample) const;  // ": ... will take at least N s ..." or ""
  std::optional<float> intersect_objects(const Ray& ray, Query& query) const;  // one of these two:
  std::optional<float> intersect_objects_through_bvh(const Ray& ray, Query& query) const;
  std::optional<float> intersect_every_object(const Ray& ray, Query& query) const;
  bool occluded_by_any_object(const Ray& ray, Query& query) const;
  std::optional<float> intersect_object(std::uint32_t object, const Ray& ray, Query& query) const;
  std::optional<float> intersect_mesh(const MeshPart& mesh, const Ray& ray, Query& query) const;
  // Whether `record` is a hit at t_hit on object `object` (a sphere, or a mesh's triangle).
  bool record_is_of_object(const HitRecord& record, std::uint32_t object, float t_hit) const;
  static std::optional<float> test_object(void* query, const Ray& ray, std::uint32_t object);
  static std::optional<float> test_triangle(void* query, const Ray& ray, std::uint32_t triangle);
  static std::optional<float> test_triangle_watched(void* query, const Ray& ray, std::uint32_t triangle);

  const Scene& scene_;
  std::vector<Sphere> spheres_;
  std::vector<Triangle> triangles_;
  // The program's own tree over every triangle (TracingFunctions::own_tree) when the scene has
  // nothing else: intersect() and occluded() go straight into it, without the records of the
  // general queries. Else nullptr.
  const TriangleTree* only_tree_ = nullptr;
  // intersect() and occluded() while a trace records (raylab/trace_recorder.h).
  std::optional<SurfaceHit> intersect_recorded(const Ray& ray) const;
  bool occluded_recorded(const Ray& ray) const;
  // What shading needs of a hit on triangles_[triangle] with the test's details, written into
  // `hit` (a SurfaceHit as constructed: no texture coordinates).
  void fill_triangle_surface_hit(SurfaceHit& hit, std::uint32_t triangle, const TriangleHit& details,
                                 const Ray& ray) const;
  std::vector<MeshPart> meshes_;
  Bvh objects_bvh_;  // over spheres_ then meshes_; empty: test every object
  TreeChoice tree_choice_;
  // The stub stage ("05_bvh" or "04_box") that made us fall back to testing every primitive;
  // said on stderr at the first query, so that nothing is said if the render fails before.
  std::string fallback_stage_;
  std::size_t brute_force_limit_ = kBruteForceLimit;
  using TriangleTestFunction = std::optional<TriangleHit> (*)(const Ray&, const glm::vec3&, const glm::vec3&,
                                                              const glm::vec3&);
  TriangleTestFunction intersect_triangle_ = intersect_ray_triangle;
  using SphereTestFunction = std::optional<float> (*)(const Ray&, const glm::vec3&, float);
  SphereTestFunction intersect_sphere_ = nullptr;  // stage 02's, unless TracingFunctions say otherwise
};

}  // namespace raylab
