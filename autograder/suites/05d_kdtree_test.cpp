// Autograder suite for stage 05d_kdtree (bonus, 20 points).
//
// The build is judged on its own: every rule of the KdTree layout, node by node, and every leaf's
// list against the boxes that reach into its cell (a primitive lost at a split is named with the
// plane it crossed); then its quality: its SAH cost against the grader's own build, and rays
// through the empty space between two clusters, which a tree that cuts empty space off crosses
// without a test. The traversal runs on the grader's own trees (so that it does not depend on
// your build), with the grader's triangle test, against brute force, and its work (the triangle
// tests the judge answers, on a mesh the stage server was never sent) against the grader's own
// front-to-back walk of the same tree. Every test is exact: no false failures.
//
// A traversal that gets some hits wrong is diagnosed from a fitted model: the grader walks its
// tree with each combination of the classic mistakes (the far side first, a hit beyond the cell
// accepted, the interval not cut at the plane) and names the mistakes of the walk whose answers
// agree with yours on the most rays (two mistakes at once are named together).
#include "05d_kdtree_calls.h"
#include "bvh_support.h"
#include "grader_geometry.h"
#include "grading.h"
#include "support.h"

#include "raylab/error.h"
#include "raylab/math.h"
#include "raylab/random.h"
#include "raylab/stages/05d_kdtree.h"
#include "raylab/testkit/random_values.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "05d_kdtree";

const bool kRegistered = register_stage(kStage, [] {
  KdTree one_leaf;
  one_leaf.bounds = Bounds3{glm::vec3(0.0f), glm::vec3(1.0f)};
  one_leaf.nodes.resize(1);
  one_leaf.nodes[0].leaf = 1;
  one_leaf.nodes[0].primitive_count = 1;
  one_leaf.primitive_indices = {0};
  const std::vector<protocol::Triangle> triangle{{glm::vec3(0, 0, -1), glm::vec3(1, 0, -1), glm::vec3(0, 1, -1)}};
  const PrimitiveIntersector intersector{grader_triangle_test, const_cast<std::vector<protocol::Triangle>*>(&triangle)};
  throw_if_every_function_is_a_stub(kStage, {[&] { (void)build_kdtree({one_leaf.bounds}); },
                                             [&] {
                                               BvhTraversalStats stats;
                                               (void)intersect_kdtree(one_leaf, Ray{}, intersector, false, stats);
                                             }});
});

std::string text(std::uint64_t value) { return std::to_string(value); }

// ---- The grader's own build (the contract's, in the plainest form) --------------------------------

double area_with(const Bounds3& cell, int axis, double extent) {
  glm::dvec3 e = glm::dvec3(cell.extent());
  e[axis] = extent;
  return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

struct GraderBuild {
  const std::vector<Bounds3>& boxes;
  KdTree tree;
  int max_depth = 0;

  void build(std::uint32_t index, const std::vector<std::uint32_t>& primitives, const Bounds3& cell, int depth) {
    int best_axis = -1;
    float best_position = 0.0f;
    double best_cost = static_cast<double>(primitives.size());  // the leaf's
    const double cell_area = cell.surface_area();
    if (depth < max_depth && primitives.size() > 1 && cell_area > 0.0)
      for (int axis = 0; axis < 3; ++axis) {
        std::vector<float> planes;
        for (const std::uint32_t p : primitives)
          for (const float face : {boxes[p].min[axis], boxes[p].max[axis]})
            if (face > cell.min[axis] && face < cell.max[axis]) planes.push_back(face);
        std::sort(planes.begin(), planes.end());
        planes.erase(std::unique(planes.begin(), planes.end()), planes.end());
        for (const float s : planes) {
          double below = 0, above = 0;
          for (const std::uint32_t p : primitives) {
            const Bounds3& box = boxes[p];
            if (box.min[axis] < s || (box.min[axis] == s && box.max[axis] == s)) ++below;
            if (box.max[axis] > s) ++above;
          }
          const double bonus = (below == 0 || above == 0) ? kKdEmptyBonus : 0.0;
          const double cost = 1.0 + (1.0 - bonus) * (area_with(cell, axis, s - cell.min[axis]) / cell_area * below +
                                                     area_with(cell, axis, cell.max[axis] - s) / cell_area * above);
          if (cost < best_cost) best_axis = axis, best_position = s, best_cost = cost;
        }
      }
    if (best_axis < 0) {
      KdNode& leaf = tree.nodes[index];
      leaf.leaf = 1;
      leaf.first_index = static_cast<std::uint32_t>(tree.primitive_indices.size());
      leaf.primitive_count = static_cast<std::uint32_t>(primitives.size());
      tree.primitive_indices.insert(tree.primitive_indices.end(), primitives.begin(), primitives.end());
      return;
    }
    std::vector<std::uint32_t> below, above;
    for (const std::uint32_t p : primitives) {
      const Bounds3& box = boxes[p];
      if (box.min[best_axis] < best_position || (box.min[best_axis] == best_position && box.max[best_axis] == best_position))
        below.push_back(p);
      if (box.max[best_axis] > best_position) above.push_back(p);
    }
    const auto first = static_cast<std::uint32_t>(tree.nodes.size());
    tree.nodes.resize(tree.nodes.size() + 2);
    tree.nodes[index].split_axis = static_cast<std::uint8_t>(best_axis);
    tree.nodes[index].split_position = best_position;
    tree.nodes[index].first_index = first;
    Bounds3 below_cell = cell, above_cell = cell;
    below_cell.max[best_axis] = best_position;
    above_cell.min[best_axis] = best_position;
    build(first, below, below_cell, depth + 1);
    build(first + 1, above, above_cell, depth + 1);
  }
};

KdTree grader_kdtree(const std::vector<Bounds3>& boxes) {
  GraderBuild builder{boxes, {}, 0};
  std::vector<std::uint32_t> primitives;
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    if (!boxes[i].is_empty()) {
      primitives.push_back(i);
      builder.tree.bounds.extend(boxes[i]);
    }
  if (primitives.empty()) return builder.tree;
  builder.max_depth = kdtree_max_depth(primitives.size());
  builder.tree.nodes.resize(1);
  builder.build(0, primitives, builder.tree.bounds, 0);
  return builder.tree;
}

// ---- The grader's walk, right or with the classic mistakes -------------------------------------

struct WalkMistakes {
  bool far_first = false;         // the far child first
  bool no_cell_check = false;     // returns after the first leaf with a hit, wherever the hit lies
  bool interval_not_cut = false;  // the near child keeps the parent's interval end (t_max not clipped)
  // When the walk ends: once the closest hit lies inside the leaf's cell (right), only when the next
  // cell starts beyond it (right answers, a little more work), or never (every cell the ray crosses).
  enum class Stop { InCell, BeyondOnly, Never } stop = Stop::InCell;
  int count() const { return int(far_first) + int(no_cell_check) + int(interval_not_cut) + int(stop != Stop::InCell); }
};

struct WalkResult {
  std::optional<BvhHit> hit;
  std::uint64_t tests = 0;
};

// The ray's interval in the closed box, in double; nullopt when it misses.
std::optional<std::pair<double, double>> interval_in(const Ray& ray, const Bounds3& box) {
  double t0 = ray.t_min, t1 = ray.t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = ray.origin[axis], d = ray.direction[axis];
    if (d == 0.0) {
      if (o < box.min[axis] || o > box.max[axis]) return std::nullopt;
      continue;
    }
    double near = (box.min[axis] - o) / d, far = (box.max[axis] - o) / d;
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
  }
  if (!(t0 <= t1)) return std::nullopt;
  return std::make_pair(t0, t1);
}

// A walk of a tree that keeps every rule (kdtree_problem finds none).
WalkResult grader_walk(const KdTree& tree, const PrimitiveIntersector& intersector, const Ray& ray, bool any_hit,
                       WalkMistakes mistakes = {}) {
  WalkResult result;
  const auto root = tree.nodes.empty() ? std::nullopt : interval_in(ray, tree.bounds);
  if (!root) return result;
  struct Cell {
    std::uint32_t node;
    double t0, t1;
    bool in_plane;  // the other side of a plane the ray lies in (the stack is out of order while one waits)
  };
  std::vector<Cell> stack{{0u, root->first, root->second, false}};
  int in_plane_waiting = 0;
  Ray search = ray;
  while (!stack.empty()) {
    Cell cell = stack.back();
    stack.pop_back();
    if (cell.in_plane) --in_plane_waiting;
    if (mistakes.stop != WalkMistakes::Stop::Never && result.hit && cell.t0 > result.hit->t_hit) {
      if (in_plane_waiting == 0) break;
      continue;
    }
    while (!tree.nodes[cell.node].is_leaf()) {
      const KdNode& node = tree.nodes[cell.node];
      const double o = ray.origin[node.split_axis], d = ray.direction[node.split_axis], split = node.split_position;
      const bool below_first = o < split || (o == split && d <= 0.0);
      std::uint32_t near = below_first ? node.first_index : node.first_index + 1;
      std::uint32_t far = below_first ? node.first_index + 1 : node.first_index;
      if (d == 0.0) {
        if (o == split) stack.push_back({far, cell.t0, cell.t1, true}), ++in_plane_waiting;
        cell.node = near;
        continue;
      }
      const double t_split = (split - o) / d;
      if (t_split > cell.t1 || t_split <= 0.0) {
        cell.node = near;
      } else if (t_split < cell.t0) {
        cell.node = far;
      } else if (mistakes.far_first) {
        stack.push_back({near, cell.t0, mistakes.interval_not_cut ? cell.t1 : t_split, false});
        cell = {far, t_split, cell.t1, false};
      } else {
        stack.push_back({far, t_split, cell.t1, false});
        cell = {near, cell.t0, mistakes.interval_not_cut ? cell.t1 : t_split, false};
      }
    }
    const KdNode& leaf = tree.nodes[cell.node];
    for (std::uint32_t i = leaf.first_index; i < leaf.first_index + leaf.primitive_count; ++i) {
      ++result.tests;
      const std::uint32_t primitive = tree.primitive_indices[i];
      if (const std::optional<float> t = intersector.test(intersector.context, search, primitive)) {
        if (any_hit) {
          result.hit = BvhHit{*t, primitive};
          return result;
        }
        search.t_max = *t;
        result.hit = BvhHit{*t, primitive};
      }
    }
    // (a cell still waiting may start before t1: the other side of a plane the ray lies in)
    if (result.hit && mistakes.stop == WalkMistakes::Stop::InCell &&
        (mistakes.no_cell_check || (result.hit->t_hit <= cell.t1 && in_plane_waiting == 0)))
      break;
  }
  return result;
}

// ---- The rules of a tree ---------------------------------------------------------------------------

// Whether a primitive's box reaches into a cell: the two meet, and not only in a face the cell
// shares with its neighbour across a plane (a box that only touches the cell from there, or lies in
// that plane, may be left to the neighbour; in a face of the root's cell it has no neighbour).
bool reaches_into(const Bounds3& box, const Bounds3& cell, const Bounds3& root) {
  for (int axis = 0; axis < 3; ++axis) {
    const float low = std::max(box.min[axis], cell.min[axis]), high = std::min(box.max[axis], cell.max[axis]);
    if (low > high) return false;
    if (low == high && cell.min[axis] < cell.max[axis] &&
        ((low == cell.min[axis] && low != root.min[axis]) || (low == cell.max[axis] && low != root.max[axis])))
      return false;
  }
  return true;
}
bool touches(const Bounds3& box, const Bounds3& cell) {
  for (int axis = 0; axis < 3; ++axis)
    if (std::max(box.min[axis], cell.min[axis]) > std::min(box.max[axis], cell.max[axis])) return false;
  return true;
}

std::string axis_text(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

struct Problem {
  Message message;
  bool lost_crossing_plane = false;  // a primitive lost where its box crosses an ancestor's plane
};

// The first rule the tree breaks, or nothing.
std::optional<Problem> kdtree_problem(const std::vector<Bounds3>& boxes, const KdTree& tree) {
  auto problem = [](MessageId id, std::vector<MessageArg> args) {
    return std::optional<Problem>(Problem{Message{id, std::move(args)}});
  };
  Bounds3 all;
  std::uint64_t with_box = 0;
  for (const Bounds3& box : boxes)
    if (!box.is_empty()) all.extend(box), ++with_box;
  if (with_box == 0)
    return tree.nodes.empty() ? std::nullopt : problem(MessageId::kd_rule_nodes_for_nothing, {});
  if (tree.nodes.empty()) return problem(MessageId::kd_rule_no_nodes, {});
  if (tree.bounds != all)
    return problem(MessageId::kd_rule_bounds, {{"got", box_text(tree.bounds)}, {"expected", box_text(all)}});
  if (tree.nodes.size() > 16 * with_box + 1)
    return problem(MessageId::kd_rule_too_many_nodes, {{"nodes", text(tree.nodes.size())}, {"count", text(with_box)}});
  const int max_depth = kdtree_max_depth(with_box);
  std::vector<bool> reached(tree.nodes.size(), false), listed(boxes.size(), false);
  struct Pending {
    std::uint32_t node;
    Bounds3 cell;
    int depth;
    std::vector<std::uint32_t> required;         // the primitives whose boxes reach into the cell
    std::vector<std::pair<int, float>> planes;  // the ancestors' planes
  };
  std::vector<std::uint32_t> everything;
  for (std::uint32_t p = 0; p < boxes.size(); ++p)
    if (!boxes[p].is_empty()) everything.push_back(p);
  std::vector<Pending> pending{{0u, all, 0, everything, {}}};
  reached[0] = true;
  while (!pending.empty()) {
    Pending at = std::move(pending.back());
    pending.pop_back();
    const KdNode& node = tree.nodes[at.node];
    if (at.depth > max_depth)
      return problem(MessageId::kd_rule_too_deep, {{"node", text(at.node)}, {"depth", text(at.depth)},
                                                   {"count", text(with_box)}, {"limit", text(max_depth)}});
    if (node.leaf > 1) return problem(MessageId::kd_rule_leaf_flag, {{"node", text(at.node)}, {"value", text(node.leaf)}});
    if (!node.is_leaf()) {
      if (node.split_axis > 2)
        return problem(MessageId::kd_rule_axis, {{"node", text(at.node)}, {"axis", text(node.split_axis)}});
      const int axis = node.split_axis;
      const float s = node.split_position;
      if (!(s > at.cell.min[axis] && s < at.cell.max[axis]))
        return problem(MessageId::kd_rule_plane_outside,
                       {{"node", text(at.node)}, {"axis", axis_text(axis)}, {"position", gtest_text(s)},
                        {"low", gtest_text(at.cell.min[axis])}, {"high", gtest_text(at.cell.max[axis])}});
      const std::uint64_t first = node.first_index;
      if (first == 0 || first + 1 >= tree.nodes.size())
        return problem(MessageId::kd_rule_child_out_of_range,
                       {{"node", text(at.node)}, {"first", text(first)}, {"size", text(tree.nodes.size())}});
      for (const std::uint64_t child : {first, first + 1}) {
        if (reached[child]) return problem(MessageId::kd_rule_reached_twice, {{"node", text(child)}});
        reached[child] = true;
      }
      Bounds3 below = at.cell, above = at.cell;
      below.max[axis] = s;
      above.min[axis] = s;
      auto planes = at.planes;
      planes.push_back({axis, s});
      std::vector<std::uint32_t> below_required, above_required;
      for (const std::uint32_t p : at.required) {
        if (reaches_into(boxes[p], below, all)) below_required.push_back(p);
        if (reaches_into(boxes[p], above, all)) above_required.push_back(p);
      }
      pending.push_back({static_cast<std::uint32_t>(first), below, at.depth + 1, std::move(below_required), planes});
      pending.push_back({static_cast<std::uint32_t>(first + 1), above, at.depth + 1, std::move(above_required), planes});
      continue;
    }
    const std::uint64_t first = node.first_index, count = node.primitive_count;
    if (first + count > tree.primitive_indices.size())
      return problem(MessageId::kd_rule_leaf_range, {{"node", text(at.node)}, {"first", text(first)},
                                                     {"count", text(count)},
                                                     {"size", text(tree.primitive_indices.size())}});
    std::set<std::uint32_t> in_leaf;
    for (std::uint64_t i = first; i < first + count; ++i) {
      const std::uint32_t p = tree.primitive_indices[i];
      if (p >= boxes.size() || boxes[p].is_empty())
        return problem(MessageId::kd_rule_bad_primitive,
                       {{"node", text(at.node)}, {"primitive", text(p)}, {"count", text(boxes.size())}});
      if (!in_leaf.insert(p).second)
        return problem(MessageId::kd_rule_listed_twice, {{"node", text(at.node)}, {"primitive", text(p)}});
      if (!touches(boxes[p], at.cell))
        return problem(MessageId::kd_rule_outside_cell, {{"node", text(at.node)}, {"primitive", text(p)},
                                                         {"box", box_text(boxes[p])}, {"cell", box_text(at.cell)}});
      listed[p] = true;
    }
    for (const std::uint32_t p : at.required)
      if (in_leaf.count(p) == 0) {
        std::optional<Problem> lost =
            problem(MessageId::kd_rule_lost, {{"node", text(at.node)}, {"primitive", text(p)},
                                              {"box", box_text(boxes[p])}, {"cell", box_text(at.cell)}});
        for (const auto& [axis, s] : at.planes)
          lost->lost_crossing_plane = lost->lost_crossing_plane || (boxes[p].min[axis] < s && boxes[p].max[axis] > s);
        return lost;
      }
  }
  for (std::size_t n = 0; n < reached.size(); ++n)
    if (!reached[n]) return problem(MessageId::kd_rule_unreached, {{"node", text(n)}});
  for (std::uint32_t p = 0; p < boxes.size(); ++p)
    if (!boxes[p].is_empty() && !listed[p])
      return problem(MessageId::kd_rule_in_no_leaf, {{"primitive", text(p)}, {"box", box_text(boxes[p])}});
  return std::nullopt;
}

// The tree's SAH cost (kKdEmptyBonus aside: what a ray pays on average): each inner node's cell's
// area over the root's, plus each leaf's times its primitive count. For a tree that keeps the rules.
double sah_cost(const KdTree& tree) {
  const double root_area = tree.bounds.surface_area();
  if (tree.nodes.empty() || !(root_area > 0.0)) return 0.0;
  double cost = 0.0;
  std::vector<std::pair<std::uint32_t, Bounds3>> pending{{0u, tree.bounds}};
  while (!pending.empty()) {
    const auto [index, cell] = pending.back();
    pending.pop_back();
    const KdNode& node = tree.nodes[index];
    const double share = cell.surface_area() / root_area;
    if (node.is_leaf()) {
      cost += share * node.primitive_count;
      continue;
    }
    cost += share;
    Bounds3 below = cell, above = cell;
    below.max[node.split_axis] = node.split_position;
    above.min[node.split_axis] = node.split_position;
    pending.push_back({node.first_index, below});
    pending.push_back({node.first_index + 1, above});
  }
  return cost;
}

// ---- Meshes of this stage ---------------------------------------------------------------------------

// Long thin triangles across the whole box among small ones: a long one listed in the first cell a
// ray opens is often hit only in a later cell, behind a small one.
const TestMesh& long_and_short_mesh() {
  static const TestMesh mesh = [] {
    Pcg32 random(511, testkit::stream_of("kd long and short"));
    std::vector<std::array<glm::vec3, 3>> triangles;
    for (int i = 0; i < 120; ++i) {
      const glm::vec3 a = testkit::random_vec3(random, -10, 10), b = testkit::random_vec3(random, -10, 10);
      triangles.push_back({a, b, b + testkit::random_vec3(random, -0.5f, 0.5f)});
    }
    for (int i = 0; i < 600; ++i) {
      const glm::vec3 center = testkit::random_vec3(random, -10, 10);
      triangles.push_back({center + testkit::random_vec3(random, -0.6f, 0.6f), center + testkit::random_vec3(random, -0.6f, 0.6f),
                           center + testkit::random_vec3(random, -0.6f, 0.6f)});
    }
    return make_test_mesh(MessageId::kd_mesh_long_and_short, std::move(triangles));
  }();
  return mesh;
}

// Two clusters of small triangles in the corners x < -9 and x > 9 of a box 22 wide: between them,
// empty space.
const TestMesh& two_clusters_mesh() {
  static const TestMesh mesh = [] {
    Pcg32 random(512, testkit::stream_of("kd two clusters"));
    std::vector<std::array<glm::vec3, 3>> triangles;
    for (int i = 0; i < 400; ++i) {
      const float side = i % 2 ? 10.0f : -10.0f;
      const glm::vec3 center = glm::vec3(side, 0.0f, 0.0f) + testkit::random_vec3(random, -0.8f, 0.8f);
      triangles.push_back({center + testkit::random_vec3(random, -0.2f, 0.2f), center + testkit::random_vec3(random, -0.2f, 0.2f),
                           center + testkit::random_vec3(random, -0.2f, 0.2f)});
    }
    return make_test_mesh(MessageId::kd_mesh_two_clusters, std::move(triangles));
  }();
  return mesh;
}

// The meshes the build and the traversal are judged on.
std::vector<const TestMesh*> kd_meshes() {
  std::vector<const TestMesh*> meshes;
  for (const TestMesh& mesh : bvh_test_meshes()) meshes.push_back(&mesh);
  meshes.push_back(&long_and_short_mesh());
  meshes.push_back(&two_clusters_mesh());
  return meshes;
}

// ---- The build ------------------------------------------------------------------------------------

struct BuildCase {
  Message name;
  std::vector<Bounds3> boxes;
};
std::vector<BuildCase> build_cases() {
  std::vector<BuildCase> cases;
  for (const TestMesh* mesh : kd_meshes()) cases.push_back({mesh->name, mesh->bounds});
  cases.push_back({Message(MessageId::kd_case_empty), {}});
  cases.push_back({Message(MessageId::kd_case_one_box), {Bounds3{}, Bounds3{glm::vec3(-1.0f), glm::vec3(2.0f)}}});
  // Two unit boxes 1 apart along x and a square in the plane x = 1 between them, where the cheapest
  // plane lies: the square goes to one side, not to neither.
  cases.push_back({Message(MessageId::kd_case_flat_in_plane),
                   {Bounds3{glm::vec3(0, 0, 0), glm::vec3(1, 1, 1)}, Bounds3{glm::vec3(1, 0, 0), glm::vec3(1, 1, 1)},
                    Bounds3{glm::vec3(2, 0, 0), glm::vec3(3, 1, 1)}}});
  // Three boxes on a line, the middle one crossing every plane between the others, and two empty
  // boxes (a primitive that has none is in no leaf).
  cases.push_back({Message(MessageId::kd_case_with_empty_boxes),
                   {Bounds3{glm::vec3(0, 0, 0), glm::vec3(1, 1, 1)}, Bounds3{}, Bounds3{glm::vec3(0.5f, 0, 0), glm::vec3(9.5f, 1, 1)},
                    Bounds3{glm::vec3(9, 0, 0), glm::vec3(10, 1, 1)}, Bounds3{}}});
  return cases;
}

GRADED_TEST(kStage, Stage05dKdTree, BuildKeepsEveryRule, 6) {
  for (const BuildCase& c : build_cases()) {
    const KdTree tree = build_kdtree(c.boxes);
    if (const std::optional<Problem> broken = kdtree_problem(c.boxes, tree)) {
      add_failure({MessageId::kd_failure_build, {{"tree", c.name}, {"problem", broken->message}}});
      if (broken->lost_crossing_plane) add_hint(MessageId::kd_lost_at_split);
      return;
    }
  }
}

GRADED_TEST(kStage, Stage05dKdTree, BuildCutsEmptySpaceAndCostsLittle, 4) {
  // Rays through the gap between the two clusters (x in (-7, 7), crossing the box along y and z):
  // the grader walks your tree; a tree that cut the empty space off tests no triangle.
  const TestMesh& clusters = two_clusters_mesh();
  const KdTree clusters_tree = build_kdtree(clusters.bounds);
  // A tree that breaks a rule has no cost to judge (BuildKeepsEveryRule says which rule): no points.
  const auto broken = [](const TestMesh& mesh) {
    add_failure({MessageId::kd_failure_cost_of_broken_tree, {{"mesh", mesh.name}}});
  };
  if (kdtree_problem(clusters.bounds, clusters_tree)) return broken(clusters);
  Pcg32 random(513, testkit::stream_of("kd gap rays"));
  std::uint64_t gap_tests = 0;
  constexpr int kGapRays = 100;
  for (int i = 0; i < kGapRays; ++i) {
    Ray ray;
    ray.origin = glm::vec3(float(testkit::random_double(random, -7.0, 7.0)), -5.0f, float(testkit::random_double(random, -3.0, 3.0)));
    ray.direction = glm::normalize(glm::vec3(0.0f, 1.0f, float(testkit::random_double(random, -0.3, 0.3))));
    gap_tests += grader_walk(clusters_tree, intersector_for(clusters), ray, false).tests;
  }
  if (gap_tests > 0) {
    add_failure({MessageId::kd_failure_empty_space, {{"tests", stream_text(double(gap_tests) / kGapRays)}, {"mesh", clusters.name}}});
    add_hint(MessageId::kd_empty_space);
  }
  for (const TestMesh* mesh : kd_meshes()) {
    const KdTree yours = build_kdtree(mesh->bounds);
    if (kdtree_problem(mesh->bounds, yours)) return broken(*mesh);
    const double cost = sah_cost(yours), reference = sah_cost(grader_kdtree(mesh->bounds));
    if (cost > 1.25 * reference + 0.05) {
      add_failure({MessageId::kd_failure_cost, {{"mesh", mesh->name}, {"cost", stream_text(cost)},
                                                {"reference", stream_text(reference)}}});
      add_hint(MessageId::kd_expensive_tree);
      return;
    }
  }
}

// ---- The traversal ---------------------------------------------------------------------------------

bool same_answer(const std::optional<BvhHit>& a, const std::optional<BvhHit>& b) {
  return a.has_value() == b.has_value() && (!a || a->t_hit == b->t_hit);
}

// Whether `got` names a primitive of the mesh that the ray really hits there (with any_hit: at
// all): the primitive a traversal returns is the one the renderer shades.
bool names_a_real_hit(const TestMesh& mesh, const Ray& ray, const std::optional<BvhHit>& got, bool any_hit) {
  if (!got) return true;
  if (got->primitive >= mesh.triangles.size()) return false;
  const PrimitiveIntersector test = intersector_for(mesh);
  const std::optional<float> t = test.test(test.context, ray, got->primitive);
  return any_hit ? t.has_value() : t == std::optional<float>(got->t_hit);
}

// What a traversal answered on the rays of one mesh, walking the grader's tree of it.
struct Evidence {
  KdTree tree;
  const TestMesh* mesh = nullptr;
  std::vector<Ray> rays;
  std::vector<std::optional<BvhHit>> answers;
  std::vector<std::uint64_t> tests;  // per ray, counted by the judge (the work test's evidence only)
};

// Every combination of the classic mistakes the fitted model tries: the order, the cell check and
// the interval's cut, each with every way of stopping (work_too: the right walk that stops only
// beyond the hit, and the one that never stops).
std::vector<WalkMistakes> walk_models(bool work_too) {
  std::vector<WalkMistakes> models;
  for (int bits = 0; bits < 8; ++bits)
    for (const WalkMistakes::Stop stop : {WalkMistakes::Stop::InCell, WalkMistakes::Stop::BeyondOnly, WalkMistakes::Stop::Never}) {
      if (!work_too && stop != WalkMistakes::Stop::InCell) continue;
      WalkMistakes model;
      model.far_first = bits & 1;
      model.no_cell_check = bits & 2;
      model.interval_not_cut = bits & 4;
      model.stop = stop;
      models.push_back(model);
    }
  return models;
}

// The model of the grader's walk that agrees with the evidence on the most rays: on the answer, and
// with by_tests on the number of tests too. Among models that agree equally, the one with the fewest
// mistakes; nullopt when two different models of those fewest mistakes agree equally (the evidence
// cannot tell them apart: no mistake is named).
std::optional<WalkMistakes> fitted_mistakes(const std::vector<Evidence>& evidence, bool by_tests) {
  std::optional<WalkMistakes> best;
  int best_agreeing = -1;
  bool tied = false;
  // The mistakes a model's hints name: models that name the same ones are no rivals.
  const auto named = [](const WalkMistakes& m) {
    return std::make_tuple(m.far_first, m.no_cell_check, m.interval_not_cut, m.stop == WalkMistakes::Stop::Never);
  };
  for (const WalkMistakes& model : walk_models(by_tests)) {
    int agreeing = 0;
    for (const Evidence& e : evidence)
      for (std::size_t r = 0; r < e.rays.size(); ++r) {
        const WalkResult walk = grader_walk(e.tree, intersector_for(*e.mesh), e.rays[r], false, model);
        agreeing += same_answer(walk.hit, e.answers[r]) && (!by_tests || walk.tests == e.tests[r]);
      }
    // (BeyondOnly is no mistake: it finds the same hits with at most one more leaf per ray)
    const int count = model.count() - (model.stop == WalkMistakes::Stop::BeyondOnly ? 1 : 0);
    const int best_count = best ? best->count() - (best->stop == WalkMistakes::Stop::BeyondOnly ? 1 : 0) : 0;
    if (agreeing > best_agreeing || (agreeing == best_agreeing && count < best_count)) {
      best = model;
      best_agreeing = agreeing;
      tied = false;
    } else if (agreeing == best_agreeing && count == best_count && named(model) != named(*best)) {
      tied = true;
    }
  }
  if (tied) return std::nullopt;
  return best;
}

// The hints of the fitted model's mistakes; `otherwise` when it names none.
void hint_walk_mistakes(const std::optional<WalkMistakes>& mistakes, MessageId otherwise) {
  bool named = false;
  if (mistakes && mistakes->no_cell_check) add_hint(MessageId::kd_hit_beyond_cell), named = true;
  if (mistakes && mistakes->interval_not_cut) add_hint(MessageId::kd_interval_not_cut), named = true;
  if (mistakes && mistakes->far_first) add_hint(MessageId::kd_far_first), named = true;
  if (mistakes && mistakes->stop == WalkMistakes::Stop::Never) add_hint(MessageId::kd_never_stops), named = true;
  if (!named) add_hint(otherwise);
}

// How the answers of the first mesh that differs differ: a hit at the wrong distance, or a hit
// missed or invented (the walk's mistakes, for the fitted model), or the right distance with a
// primitive that is not hit there (the index returned).
struct Differences {
  bool wrong_hit = false;
  bool wrong_primitive = false;
};

// Your answers on the grader's trees against brute force (up to 3 differences shown); the rays of
// the first mesh that differs are the evidence for the fitted model.
Differences compare_with_brute_force(bool any_hit, bool axis_aligned, const Message& what, std::vector<Evidence>& evidence) {
  Differences found;
  std::uint32_t seed = any_hit ? 1700 : axis_aligned ? 1800 : 1600;
  for (const TestMesh* mesh : kd_meshes()) {
    Evidence e{grader_kdtree(mesh->bounds), mesh, rays_at(*mesh, 300, seed++, axis_aligned), {}, {}};
    e.answers = intersect_kdtree_each(e.tree, mesh->triangles, e.rays, any_hit);
    int differences = 0;
    for (std::size_t r = 0; r < e.rays.size(); ++r) {
      const std::optional<BvhHit> expected = brute_force_closest(*mesh, e.rays[r]);
      const bool right_hit =
          any_hit ? e.answers[r].has_value() == expected.has_value() : same_answer(e.answers[r], expected);
      const bool real_hit = names_a_real_hit(*mesh, e.rays[r], e.answers[r], any_hit);
      if (!right_hit) found.wrong_hit = true;
      else if (!real_hit) found.wrong_primitive = true;
      if ((right_hit && real_hit) || ++differences > 3) continue;
      auto hit_of = [](const std::optional<BvhHit>& hit) {
        if (!hit) return Message(MessageId::value_no_hit);
        return Message(MessageId::value_t_primitive, {{"t", std::to_string(hit->t_hit)}, {"primitive", std::to_string(hit->primitive)}});
      };
      add_failure({MessageId::bvh_failure_ray, {{"what", what}, {"mesh", mesh->name}, {"index", std::to_string(r)},
                                                {"ray", ray_text(e.rays[r])}, {"expected", hit_of(expected)},
                                                {"got", hit_of(e.answers[r])}}});
    }
    if (differences == 0) continue;
    evidence.push_back(std::move(e));
    return found;
  }
  return found;
}

GRADED_TEST(kStage, Stage05dKdTree, ClosestHitsMatchBruteForce, 5) {
  std::vector<Evidence> evidence;
  const Differences any_ray = compare_with_brute_force(false, false, MessageId::bvh_what_closest_hit, evidence);
  const Differences aligned = compare_with_brute_force(false, true, MessageId::bvh_what_closest_hit_axis_aligned, evidence);
  if (any_ray.wrong_primitive || aligned.wrong_primitive) add_hint(MessageId::kd_wrong_primitive);
  if (any_ray.wrong_hit || aligned.wrong_hit) hint_walk_mistakes(fitted_mistakes(evidence, false), MessageId::kd_not_closest);
}

GRADED_TEST(kStage, Stage05dKdTree, AnyHitAgreesWithBruteForce, 2) {
  std::vector<Evidence> evidence;
  if (compare_with_brute_force(true, false, MessageId::bvh_what_any_hit, evidence).wrong_primitive)
    add_hint(MessageId::kd_wrong_primitive_any_hit);
  // And it returns at once: after the first hit the intersector reports, no more tests (20 rays on
  // the grader's tree: each test is a call into the judge).
  const TestMesh& mesh = work_test_mesh();
  const KdTree tree = grader_kdtree(mesh.bounds);
  std::uint64_t rays_after = 0, calls_after = 0;
  const std::vector<Ray> rays = rays_at(mesh, 20, 1901);
  for (const Ray& ray : rays) {
    TestsAfterAHit probe{intersector_for(mesh)};
    BvhTraversalStats stats;
    (void)intersect_kdtree(tree, ray, PrimitiveIntersector{TestsAfterAHit::test, &probe}, true, stats);
    rays_after += probe.calls > 0;
    calls_after += probe.calls;
  }
  if (rays_after > 0)
    add_failure({MessageId::kd_failure_any_hit_goes_on,
                 {{"rays", std::to_string(rays_after)}, {"total", std::to_string(rays.size())}, {"calls", std::to_string(calls_after)}}});
}

// Work on the bunny turned and moved for this run (work_test_mesh: your process was never sent its
// triangles): the primitive tests, counted by the judge (each one is a question your process asks
// it), against the grader's own front-to-back walk of the same tree. The hits must be brute
// force's, or the work counts for nothing. Allowed: 25% more tests and one more per ray (a tie at a
// plane may be walked either way). stats.primitives_tested must be exactly the tests the judge
// answered, and stats.nodes_visited must count something.
GRADED_TEST(kStage, Stage05dKdTree, DoesNoMoreWorkThanTheReference, 3) {
  const TestMesh& mesh = work_test_mesh();
  const KdTree tree = grader_kdtree(mesh.bounds);
  std::vector<Ray> rays = rays_at(mesh, 300, 1900);
  struct Work {
    std::uint64_t tests = 0, reported_tests = 0, nodes = 0, wrong = 0;
  };
  // Your walk of each ray, its tests counted by the judge: the evidence of the work's fitted model.
  Evidence e{tree, &mesh, {}, {}, {}};
  Work yours;
  CountedTests counted{intersector_for(mesh)};
  const auto walk = [&](const Ray& ray) {
    BvhTraversalStats stats;
    const std::uint64_t before = counted.tests;
    const std::optional<BvhHit> hit = intersect_kdtree(tree, ray, PrimitiveIntersector{counting_test, &counted}, false, stats);
    if (!same_answer(hit, brute_force_closest(mesh, ray)) || !names_a_real_hit(mesh, ray, hit, false)) ++yours.wrong;
    yours.nodes += stats.nodes_visited;
    yours.reported_tests += stats.primitives_tested;
    e.rays.push_back(ray);
    e.answers.push_back(hit);
    e.tests.push_back(counted.tests - before);
  };
  const auto model_tests = [&](const std::vector<Ray>& some) {
    std::uint64_t tests = 0;
    for (const Ray& ray : some) tests += grader_walk(tree, intersector_for(mesh), ray, false).tests;
    return tests;
  };
  // A traversal that tests nearly everything is judged on the first 10 rays: each of its tests is a
  // round trip to the judge, and its verdict is plain by then.
  const std::vector<Ray> first_rays(rays.begin(), rays.begin() + 10);
  for (const Ray& ray : first_rays) walk(ray);
  if (counted.tests > 10 * model_tests(first_rays) + 100) rays = first_rays;
  else
    for (std::size_t r = first_rays.size(); r < rays.size(); ++r) walk(rays[r]);
  yours.tests = counted.tests;
  if (yours.wrong > 0) {
    add_failure({MessageId::work_failure_wrong_hits,
                 {{"wrong", gtest_text(yours.wrong)}, {"rays", gtest_text(rays.size())}, {"mesh", mesh.name}}});
    return;
  }
  const double per_ray = double(yours.tests) / double(rays.size());
  const double reference_per_ray = double(model_tests(rays)) / double(rays.size());
  if (per_ray > 1.25 * reference_per_ray + 1.0) {
    add_failure({MessageId::kd_failure_work,
                 {{"tests", stream_text(per_ray)}, {"reference", stream_text(reference_per_ray)}, {"mesh", mesh.name}}});
    hint_walk_mistakes(fitted_mistakes({e}, true), MessageId::kd_too_much_work);
  }
  if (yours.nodes == 0) add_failure({MessageId::kd_failure_nodes_not_counted, {}});
  if (yours.reported_tests != yours.tests) {
    add_hint(MessageId::bvh_stats_not_counted);
    add_failure({MessageId::bvh_failure_stats,
                 {{"counted", stream_text(double(yours.reported_tests) / double(rays.size()))}, {"tested", stream_text(per_ray)}}});
  }
}

}  // namespace
}  // namespace raylab::grading
