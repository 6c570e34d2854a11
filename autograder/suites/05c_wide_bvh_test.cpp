// Autograder suite for stage 05c_wide_bvh (bonus, 20 points).
//
// The collapse is judged on the grader's own median trees (bvh_support.h: grader_median_tree),
// so that it does not depend on your build_bvh: every rule of the Bvh4 layout is checked node by
// node, the leaves against the binary tree's, and the tree must be wide (at most 3 n / 4 + 1 nodes
// for n binary inner nodes: pulling grandchildren up gives n / 3 to 2 n / 3, no collapse n). The
// four-box test is
// judged lane by lane against the slab test in double precision: a lane whose box the ray meets
// must be reported (stage 04's rule: never lose a hit), a lane reported must be within rounding
// of the box, and its entry distance within rounding of the exact one. The traversal runs on the
// grader's own collapse of those trees, with the grader's triangle test (run in the stage server),
// against brute force, and its work (the triangle tests the judge answers, on a mesh the stage
// server was never sent) against the grader's own near-first 4-wide traversal. Every test is
// exact: no false failures.
#include "05c_wide_bvh_calls.h"
#include "bvh_support.h"
#include "grader_geometry.h"
#include "grading.h"
#include "support.h"

#include "raylab/error.h"
#include "raylab/math.h"
#include "raylab/stages/05c_wide_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "05c_wide_bvh";
constexpr int kLeafSize = 4;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

const bool kRegistered = register_stage(kStage, [] {
  Bvh one_leaf;
  one_leaf.nodes.resize(1);
  one_leaf.nodes[0].primitive_count = 1;
  one_leaf.primitive_order = {0};
  Bvh4 wide;
  wide.nodes.push_back(empty_bvh4_node());
  wide.primitive_order = {0};
  const std::vector<protocol::Triangle> triangle{{glm::vec3(0, 0, -1), glm::vec3(1, 0, -1), glm::vec3(0, 1, -1)}};
  const PrimitiveIntersector intersector{grader_triangle_test, const_cast<std::vector<protocol::Triangle>*>(&triangle)};
  throw_if_every_function_is_a_stub(kStage, {[&] { (void)collapse_bvh4(one_leaf); },
                                             [&] { (void)box4_answers({Ray{}}, {empty_bvh4_node()}); },
                                             [&] {
                                               BvhTraversalStats stats;
                                               (void)intersect_bvh4(wide, Ray{}, intersector, false, stats);
                                             }});
});

std::string text(std::uint64_t value) { return std::to_string(value); }

// ---- The grader's own collapse and traversal (the contract's, in the plainest form) --------

void set_slot(Bvh4Node& node, int slot, const Bounds3& box) {
  node.min_x[slot] = box.min.x, node.min_y[slot] = box.min.y, node.min_z[slot] = box.min.z;
  node.max_x[slot] = box.max.x, node.max_y[slot] = box.max.y, node.max_z[slot] = box.max.z;
}

std::uint32_t grader_collapse_node(const Bvh& binary, std::uint32_t index, Bvh4& wide) {
  const auto at = static_cast<std::uint32_t>(wide.nodes.size());
  wide.nodes.push_back(empty_bvh4_node());
  std::vector<std::uint32_t> children;
  const BvhNode& node = binary.nodes[index];
  if (node.is_leaf()) children = {index};
  else children = {node.first_index, node.first_index + 1};
  while (children.size() < 4) {
    int widest = -1;
    for (std::size_t i = 0; i < children.size(); ++i)
      if (!binary.nodes[children[i]].is_leaf() &&
          (widest < 0 || binary.nodes[children[i]].bounds.surface_area() >
                             binary.nodes[children[static_cast<std::size_t>(widest)]].bounds.surface_area()))
        widest = static_cast<int>(i);
    if (widest < 0) break;
    const std::uint32_t opened = binary.nodes[children[static_cast<std::size_t>(widest)]].first_index;
    children[static_cast<std::size_t>(widest)] = opened;
    children.push_back(opened + 1);
  }
  wide.nodes[at].child_count = static_cast<std::uint8_t>(children.size());
  for (std::size_t i = 0; i < children.size(); ++i) {
    const BvhNode& child = binary.nodes[children[i]];
    set_slot(wide.nodes[at], static_cast<int>(i), child.bounds);
    if (child.is_leaf()) {
      wide.nodes[at].child[i] = child.first_index;
      wide.nodes[at].primitive_count[i] = child.primitive_count;
    } else {
      const std::uint32_t below = grader_collapse_node(binary, children[i], wide);
      wide.nodes[at].child[i] = below;
    }
  }
  return at;
}

Bvh4 grader_collapse(const Bvh& binary) {
  Bvh4 wide;
  if (binary.nodes.empty()) return wide;
  wide.primitive_order = binary.primitive_order;
  grader_collapse_node(binary, 0, wide);
  return wide;
}

// The slab test in double, without rounding slack: the exact entry distance (clipped to
// t_min) when the ray meets the closed box within [t_min, t_max]. `grow` widens the box and the
// interval by that fraction of their size (the tolerance for a lane reported but not met).
std::optional<double> exact_entry(const Ray& ray, const Bounds3& box, double grow = 0.0) {
  double enter = ray.t_min, exit = ray.t_max;
  if (grow > 0.0) {
    enter -= grow * (std::fabs(enter) + 1.0);
    exit += grow * (std::fabs(exit) + 1.0);
  }
  for (int axis = 0; axis < 3; ++axis) {
    double low = box.min[axis], high = box.max[axis];
    if (grow > 0.0) {
      const double pad = grow * (high - low + std::fabs(low) + std::fabs(high) + 1.0);
      low -= pad;
      high += pad;
    }
    const double origin = ray.origin[axis], direction = ray.direction[axis];
    if (direction == 0.0) {
      if (origin < low || origin > high) return std::nullopt;
      continue;
    }
    double near = (low - origin) / direction, far = (high - origin) / direction;
    if (near > far) std::swap(near, far);
    enter = std::max(enter, near);
    exit = std::min(exit, far);
  }
  if (!(enter <= exit)) return std::nullopt;
  return enter;
}

// Near first, as the contract says, with exact box tests: the work a good traversal does.
struct GraderWork {
  std::uint64_t nodes = 0, tests = 0;
};
GraderWork grader_traversal_work(const Bvh4& wide, const TestMesh& mesh, const std::vector<Ray>& rays) {
  GraderWork work;
  const PrimitiveIntersector intersector = intersector_for(mesh);
  for (const Ray& ray : rays) {
    Ray search = ray;
    std::vector<std::pair<double, std::uint32_t>> stack{{ray.t_min, 0u}};
    while (!stack.empty()) {
      const auto [enter, index] = stack.back();
      stack.pop_back();
      if (enter > search.t_max) continue;
      const Bvh4Node& node = wide.nodes[index];
      ++work.nodes;
      std::vector<std::pair<double, int>> hit;
      for (int i = 0; i < node.child_count; ++i)
        if (const std::optional<double> entry = exact_entry(search, node.child_bounds(i))) hit.push_back({*entry, i});
      std::sort(hit.begin(), hit.end());
      for (const auto& [entry, slot] : hit) {
        if (!node.is_leaf(slot) || entry > search.t_max) continue;
        for (std::uint32_t k = node.child[slot]; k < node.child[slot] + node.primitive_count[slot]; ++k) {
          ++work.tests;
          if (const std::optional<float> t = intersector.test(intersector.context, search, wide.primitive_order[k]))
            search.t_max = *t;
        }
      }
      for (auto it = hit.rbegin(); it != hit.rend(); ++it)
        if (!node.is_leaf(it->second)) stack.push_back({it->first, node.child[it->second]});
    }
  }
  return work;
}

// ---- The collapse ------------------------------------------------------------------------------

struct LeafKey {
  std::uint32_t first = 0, count = 0;
  std::array<float, 6> box{};
  bool operator<(const LeafKey& other) const {
    return std::tie(first, count, box) < std::tie(other.first, other.count, other.box);
  }
};
LeafKey leaf_key(std::uint32_t first, std::uint32_t count, const Bounds3& box) {
  return {first, count, {box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z}};
}

bool contains(const Bounds3& outer, const Bounds3& inner) {
  return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && outer.min.z <= inner.min.z &&
         outer.max.x >= inner.max.x && outer.max.y >= inner.max.y && outer.max.z >= inner.max.z;
}

// The first rule the wide tree breaks, or nothing.
std::optional<Message> collapse_problem(const Bvh& binary, const Bvh4& wide) {
  auto problem = [](MessageId id, std::initializer_list<std::pair<const char*, std::string>> values) {
    std::vector<MessageArg> args;
    for (const auto& [name, value] : values) args.emplace_back(name, value);
    return std::optional<Message>(Message{id, args});
  };
  if (wide.primitive_order != binary.primitive_order) return problem(MessageId::wide_rule_order_changed, {});
  if (binary.nodes.empty())
    return wide.nodes.empty() ? std::nullopt : problem(MessageId::wide_rule_nodes_for_nothing, {});
  if (wide.nodes.empty()) return problem(MessageId::wide_rule_no_nodes, {});
  std::map<LeafKey, int> leaves;  // the binary tree's, each to be met once
  for (const BvhNode& node : binary.nodes)
    if (node.is_leaf()) ++leaves[leaf_key(node.first_index, node.primitive_count, node.bounds)];
  std::vector<bool> reached(wide.nodes.size(), false);
  std::vector<std::uint32_t> pending{0};
  reached[0] = true;
  while (!pending.empty()) {
    const std::uint32_t index = pending.back();
    pending.pop_back();
    const Bvh4Node& node = wide.nodes[index];
    const bool lone_leaf_root = index == 0 && binary.nodes[0].is_leaf();
    if (node.child_count < (lone_leaf_root ? 1 : 2) || node.child_count > 4)
      return problem(MessageId::wide_rule_child_count, {{"node", text(index)}, {"count", text(node.child_count)}});
    for (int slot = 0; slot < kBvh4Width; ++slot) {
      const std::string slot_text = std::to_string(slot);
      if (slot >= node.child_count) {
        const Bounds3 box = node.child_bounds(slot);
        const bool empty = box.min == glm::vec3(kInfinity) && box.max == glm::vec3(-kInfinity) &&
                           node.child[slot] == 0 && node.primitive_count[slot] == 0;
        if (!empty) return problem(MessageId::wide_rule_empty_slot, {{"node", text(index)}, {"slot", slot_text}});
        continue;
      }
      if (node.is_leaf(slot)) {
        auto found = leaves.find(leaf_key(node.child[slot], node.primitive_count[slot], node.child_bounds(slot)));
        if (found == leaves.end() || found->second == 0)
          return problem(MessageId::wide_rule_leaf_not_binary,
                         {{"node", text(index)}, {"slot", slot_text}, {"first", text(node.child[slot])},
                          {"count", text(node.primitive_count[slot])}});
        --found->second;
        continue;
      }
      const std::uint32_t child = node.child[slot];
      if (child >= wide.nodes.size() || child == 0)
        return problem(MessageId::wide_rule_child_out_of_range,
                       {{"node", text(index)}, {"slot", slot_text}, {"child", text(child)}, {"size", text(wide.nodes.size())}});
      if (reached[child]) return problem(MessageId::wide_rule_reached_twice, {{"node", text(child)}});
      reached[child] = true;
      const Bvh4Node& below = wide.nodes[child];
      for (int k = 0; k < std::min<int>(below.child_count, kBvh4Width); ++k)
        if (!contains(node.child_bounds(slot), below.child_bounds(k)))
          return problem(MessageId::wide_rule_box_too_small, {{"node", text(index)}, {"slot", slot_text}, {"child", text(child)}});
      pending.push_back(child);
    }
  }
  for (std::size_t i = 0; i < reached.size(); ++i)
    if (!reached[i]) return problem(MessageId::wide_rule_unreached, {{"node", text(i)}});
  for (const auto& [key, left] : leaves)
    if (left != 0)
      return problem(MessageId::wide_rule_leaf_missing, {{"first", text(key.first)}, {"count", text(key.count)}});
  return std::nullopt;
}

// The trees the collapse is judged on: each test mesh's median tree, and the tiny ones.
struct Case {
  Message name;
  Bvh binary;
};
std::vector<Case> collapse_cases() {
  std::vector<Case> cases;
  for (const TestMesh& mesh : bvh_test_meshes()) cases.push_back({mesh.name, grader_median_tree(mesh.bounds, kLeafSize)});
  const std::vector<Bounds3> three(3, Bounds3{glm::vec3(0.0f), glm::vec3(1.0f)});
  cases.push_back({Message(MessageId::wide_tree_one_leaf), grader_median_tree(three, kLeafSize)});
  cases.push_back({Message(MessageId::wide_tree_empty), Bvh{}});
  return cases;
}

GRADED_TEST(kStage, Stage05cWideBvh, CollapseKeepsEveryRule, 6) {
  for (const Case& c : collapse_cases()) {
    const Bvh4 wide = collapse_bvh4(c.binary);
    if (const std::optional<Message> broken = collapse_problem(c.binary, wide)) {
      add_failure({MessageId::wide_failure_collapse, {{"tree", c.name}, {"problem", *broken}}});
      return;
    }
  }
}

GRADED_TEST(kStage, Stage05cWideBvh, CollapseIsWide, 3) {
  for (const Case& c : collapse_cases()) {
    std::uint64_t inner = 0;
    for (const BvhNode& node : c.binary.nodes) inner += node.is_leaf() ? 0 : 1;
    if (inner < 2) continue;
    const Bvh4 wide = collapse_bvh4(c.binary);
    if (collapse_problem(c.binary, wide)) continue;  // CollapseKeepsEveryRule says why
    const std::uint64_t limit = 3 * inner / 4 + 1;
    if (wide.nodes.size() <= limit) continue;
    add_failure({MessageId::wide_failure_not_wide,
                 {{"tree", c.name}, {"nodes", text(wide.nodes.size())}, {"inner", text(inner)}, {"limit", text(limit)}}});
    add_hint(MessageId::wide_not_collapsed);
    return;
  }
}

// ---- Four boxes at once --------------------------------------------------------------------------

// Nodes whose slots hold the boxes of a wide tree (the bunny's, collapsed by the grader), with
// the rays that test them: rays at the bunny, and rays along the axes that start exactly on a
// box's face plane (0 * infinity) or graze its edges.
struct BoxCase {
  Ray ray;
  Bvh4Node node;
};
std::vector<BoxCase> box_cases() {
  const TestMesh& bunny = bvh_test_meshes()[0];
  const Bvh4 wide = grader_collapse(grader_median_tree(bunny.bounds, kLeafSize));
  std::vector<BoxCase> cases;
  const std::vector<Ray> rays = rays_at(bunny, 400, 51);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Ray ray = rays[i];
    if (i % 3 == 1) ray.t_max = 0.5f * glm::length(ray.origin);  // stopped short of some boxes
    cases.push_back({ray, wide.nodes[(i * 7) % std::min<std::size_t>(wide.nodes.size(), 64)]});
  }
  // A node of three unit boxes side by side along x, and rays in their faces and along their edges.
  Bvh4Node row = empty_bvh4_node();
  row.child_count = 3;
  for (int i = 0; i < 3; ++i) {
    set_slot(row, i, Bounds3{glm::vec3(float(2 * i), 0.0f, 0.0f), glm::vec3(float(2 * i + 1), 1.0f, 1.0f)});
    row.primitive_count[i] = 1;
    row.child[i] = static_cast<std::uint32_t>(i);
  }
  const glm::vec3 edge_points[] = {{-1, 0, 0}, {-1, 1, 1}, {-1, 0, 1}, {-1, 0.5f, 0}, {-1, 1, 0.5f}, {-1, 0.5f, 0.5f}};
  for (const glm::vec3& origin : edge_points)
    for (const float sign : {1.0f, -1.0f}) {
      Ray ray;
      ray.origin = sign > 0 ? origin : origin + glm::vec3(7, 0, 0);
      ray.direction = glm::vec3(sign, 0.0f, 0.0f);
      cases.push_back({ray, row});
      Ray negative_zero = ray;  // -0 components: 1 / -0 = -infinity
      negative_zero.direction = glm::vec3(sign, -0.0f, -0.0f);
      cases.push_back({negative_zero, row});
    }
  for (int i = 0; i < 3; ++i) {  // straight down onto each box, from its face planes
    Ray ray;
    ray.origin = glm::vec3(float(2 * i), 3.0f, 0.0f);
    ray.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    cases.push_back({ray, row});
    ray.origin = glm::vec3(float(2 * i + 1), 3.0f, 1.0f);
    cases.push_back({ray, row});
  }
  Ray inside;  // from inside the middle box
  inside.origin = glm::vec3(2.5f, 0.5f, 0.5f);
  inside.direction = glm::normalize(glm::vec3(1, 2, 3));
  cases.push_back({inside, row});
  // Every box wholly behind the ray: past the row and leaving it, each way along x.
  for (const float sign : {1.0f, -1.0f}) {
    Ray away;
    away.origin = glm::vec3(sign > 0 ? 7.0f : -2.0f, 0.5f, 0.5f);
    away.direction = glm::normalize(glm::vec3(sign, 0.1f, 0.05f));
    cases.push_back({away, row});
  }
  return cases;
}

GRADED_TEST(kStage, Stage05cWideBvh, BoxTestNeverLosesAHit, 4) {
  const std::vector<BoxCase> cases = box_cases();
  std::vector<Ray> rays;
  std::vector<Bvh4Node> nodes;
  for (const BoxCase& c : cases) {
    rays.push_back(c.ray);
    nodes.push_back(c.node);
  }
  const std::vector<Box4Answer> answers = box4_answers(rays, nodes);
  int failures = 0;
  bool lost_zero_component = false, empty_slot_reported = false, beyond_t_max = false, behind = false;
  for (std::size_t i = 0; i < cases.size() && failures < 3; ++i) {
    const Ray& ray = cases[i].ray;
    const Bvh4Node& node = cases[i].node;
    for (int slot = 0; slot < kBvh4Width && failures < 3; ++slot) {
      const bool reported = (answers[i].mask >> slot) & 1u;
      const Message where{MessageId::wide_box_case,
                          {{"ray", ray_text(ray)}, {"slot", std::to_string(slot)}, {"count", text(node.child_count)}}};
      if (slot >= node.child_count) {
        if (reported && !empty_slot_reported) {  // once: the lanes in use may have mistakes of their own
          empty_slot_reported = true;
          add_failure({MessageId::wide_failure_empty_slot, {{"where", where}}});
          add_hint(MessageId::wide_empty_slot);
        }
        continue;
      }
      const Bounds3 box = node.child_bounds(slot);
      const std::optional<double> entry = exact_entry(ray, box);
      if (entry && !reported) {
        ++failures;
        add_failure({MessageId::wide_failure_box_lost,
                     {{"where", where}, {"box", box_text(box)}, {"t", std::to_string(*entry)}}});
        if (ray.direction.x == 0.0f || ray.direction.y == 0.0f || ray.direction.z == 0.0f) lost_zero_component = true;
        else add_hint(MessageId::wide_box_rounding);
        continue;
      }
      if (!reported) continue;
      if (!exact_entry(ray, box, 1e-5)) {
        ++failures;
        add_failure({MessageId::wide_failure_box_false, {{"where", where}, {"box", box_text(box)}}});
        Ray unbounded = ray;
        unbounded.t_max = kInfinity;
        if (!std::isinf(ray.t_max) && exact_entry(unbounded, box)) beyond_t_max = true;
        Ray backwards = ray;  // the same line before the ray's start
        backwards.t_min = -kInfinity;
        backwards.t_max = ray.t_min;
        if (exact_entry(backwards, box)) behind = true;
        continue;
      }
      if (!entry) continue;  // within rounding of the box: its entry distance is anyone's guess
      const float got = answers[i].entry_distances[static_cast<std::size_t>(slot)];
      const double expected = *entry;
      if (!(std::fabs(got - expected) <= 1e-4 * (std::fabs(expected) + 1.0))) {
        ++failures;
        add_failure({MessageId::wide_failure_box_entry,
                     {{"where", where}, {"box", box_text(box)}, {"got", gtest_text(got)}, {"expected", std::to_string(expected)}}});
        add_hint(MessageId::wide_box_entry);
      }
    }
  }
  if (lost_zero_component) add_hint(MessageId::wide_box_zero_component);
  if (beyond_t_max) add_hint(MessageId::wide_box_beyond_t_max);
  if (behind) add_hint(MessageId::wide_box_behind);
}

// ---- The traversal ---------------------------------------------------------------------------

std::optional<BvhHit> student_hit(const Bvh4& wide, const TestMesh& mesh, const Ray& ray, bool any_hit,
                                  BvhTraversalStats& stats) {
  return intersect_bvh4(wide, ray, intersector_for(mesh), any_hit, stats);
}

void expect_brute_force_answers(bool any_hit, bool axis_aligned, const Message& what) {
  std::uint32_t seed = any_hit ? 700 : axis_aligned ? 800 : 600;
  int differences = 0;
  for (const TestMesh& mesh : bvh_test_meshes()) {
    if (differences > 0) break;
    const Bvh4 wide = grader_collapse(grader_median_tree(mesh.bounds, kLeafSize));
    const std::vector<Ray> rays = rays_at(mesh, 300, seed++, axis_aligned);
    std::vector<std::optional<BvhHit>> answers;
    for (const Ray& ray : rays) {
      BvhTraversalStats stats;
      answers.push_back(student_hit(wide, mesh, ray, any_hit, stats));
    }
    differences += compare_traversal_with_brute_force(answers, false, mesh, rays, any_hit, what);
  }
}

GRADED_TEST(kStage, Stage05cWideBvh, ClosestHitsMatchBruteForce, 4) {
  expect_brute_force_answers(false, false, MessageId::bvh_what_closest_hit);
  expect_brute_force_answers(false, true, MessageId::bvh_what_closest_hit_axis_aligned);
}

GRADED_TEST(kStage, Stage05cWideBvh, AnyHitAgreesWithBruteForce, 1) {
  expect_brute_force_answers(true, false, MessageId::bvh_what_any_hit);
  // And it returns at once: after the first hit the intersector reports, no more tests (20 rays
  // on the grader's tree: each test is a call into the judge).
  const TestMesh& mesh = work_test_mesh();
  const Bvh4 wide = grader_collapse(grader_median_tree(mesh.bounds, kLeafSize));
  std::uint64_t rays_after = 0, calls_after = 0;
  const std::vector<Ray> rays = rays_at(mesh, 20, 901);
  for (const Ray& ray : rays) {
    TestsAfterAHit probe{intersector_for(mesh)};
    BvhTraversalStats stats;
    (void)intersect_bvh4(wide, ray, PrimitiveIntersector{TestsAfterAHit::test, &probe}, true, stats);
    rays_after += probe.calls > 0;
    calls_after += probe.calls;
  }
  if (rays_after > 0)
    add_failure({MessageId::wide_failure_any_hit_goes_on,
                 {{"rays", std::to_string(rays_after)}, {"total", std::to_string(rays.size())},
                  {"calls", std::to_string(calls_after)}}});
}

// The nodes a ray's traversal surely visited, as the judge sees them: every wide node holding a
// leaf whose triangles were tested (its four boxes were tested to enter that leaf), and every
// node above it. An intersector that counts the tests and marks those nodes.
class VisitedNodes {
 public:
  VisitedNodes(const Bvh4& wide, const TestMesh& mesh) : counted_{intersector_for(mesh)} {
    node_of_primitive_.assign(mesh.triangles.size(), kNone);
    parent_.assign(wide.nodes.size(), kNone);
    marked_.assign(wide.nodes.size(), false);
    for (std::uint32_t n = 0; n < wide.nodes.size(); ++n) {
      const Bvh4Node& node = wide.nodes[n];
      for (int slot = 0; slot < node.child_count; ++slot) {
        if (!node.is_leaf(slot)) {
          parent_[node.child[slot]] = n;
          continue;
        }
        for (std::uint32_t k = node.child[slot]; k < node.child[slot] + node.primitive_count[slot]; ++k)
          node_of_primitive_[wide.primitive_order[k]] = n;
      }
    }
  }
  PrimitiveIntersector intersector() { return PrimitiveIntersector{&VisitedNodes::test, this}; }
  std::uint64_t tests() const { return counted_.tests; }
  // The nodes marked since the last call, and a fresh start for the next ray.
  std::size_t take_ray_count() {
    for (const std::uint32_t n : marked_list_) marked_[n] = false;
    const std::size_t count = marked_list_.size();
    marked_list_.clear();
    return count;
  }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  static std::optional<float> test(void* context, const Ray& ray, std::uint32_t primitive) {
    VisitedNodes& self = *static_cast<VisitedNodes*>(context);
    if (primitive < self.node_of_primitive_.size())
      for (std::uint32_t n = self.node_of_primitive_[primitive]; n != kNone && !self.marked_[n]; n = self.parent_[n]) {
        self.marked_[n] = true;
        self.marked_list_.push_back(n);
      }
    return counting_test(&self.counted_, ray, primitive);
  }
  CountedTests counted_;
  std::vector<std::uint32_t> node_of_primitive_, parent_, marked_list_;
  std::vector<bool> marked_;
};

// Work on the bunny turned and moved for this run (work_test_mesh: your process was never sent
// its triangles): the primitive tests, counted by the judge (each one is a question your process
// asks it), against the grader's own near-first traversal of the same tree. The hits must be
// brute force's, or the work counts for nothing. Allowed: 25% more tests (ties in entry distance
// may be broken either way). stats.primitives_tested must be exactly the tests the judge answered,
// and stats.nodes_visited (counted in your process) never below the nodes the judge knows were
// visited (VisitedNodes).
GRADED_TEST(kStage, Stage05cWideBvh, DoesNoMoreWorkThanTheReference, 2) {
  const TestMesh& mesh = work_test_mesh();
  const Bvh4 wide = grader_collapse(grader_median_tree(mesh.bounds, kLeafSize));
  std::vector<Ray> rays = rays_at(mesh, 300, 900);
  struct Work {
    std::uint64_t tests = 0, reported_tests = 0, nodes = 0, wrong = 0, rays_nodes_under_reported = 0;
  };
  const auto yours_on = [&](const std::vector<Ray>& some) {
    VisitedNodes visited(wide, mesh);
    const PrimitiveIntersector probe = visited.intersector();
    Work work;
    for (const Ray& ray : some) {
      BvhTraversalStats stats;
      const std::optional<BvhHit> hit = intersect_bvh4(wide, ray, probe, false, stats);
      const std::optional<BvhHit> expected = brute_force_closest(mesh, ray);
      if (hit.has_value() != expected.has_value() || (hit && hit->t_hit != expected->t_hit)) ++work.wrong;
      work.nodes += stats.nodes_visited;
      work.reported_tests += stats.primitives_tested;
      if (stats.nodes_visited < visited.take_ray_count()) ++work.rays_nodes_under_reported;
    }
    work.tests = visited.tests();
    return work;
  };
  // A traversal that tests nearly everything is judged on the first 10 rays: each of its tests is
  // a round trip to the judge, and its verdict is plain by then.
  const std::vector<Ray> first_rays(rays.begin(), rays.begin() + 10);
  Work yours = yours_on(first_rays);
  GraderWork reference = grader_traversal_work(wide, mesh, first_rays);
  if (yours.tests > 10 * reference.tests + 100) {
    rays = first_rays;
  } else {
    yours = yours_on(rays);
    reference = grader_traversal_work(wide, mesh, rays);
  }
  if (yours.wrong > 0) {
    add_failure({MessageId::work_failure_wrong_hits,
                 {{"wrong", gtest_text(yours.wrong)}, {"rays", gtest_text(rays.size())}, {"mesh", mesh.name}}});
    return;
  }
  const double per_ray = double(yours.tests) / double(rays.size());
  const double reference_per_ray = double(reference.tests) / double(rays.size());
  if (per_ray > 1.25 * reference_per_ray + 1.0) {
    add_failure({MessageId::wide_failure_work,
                 {{"tests", stream_text(per_ray)}, {"reference", stream_text(reference_per_ray)}, {"mesh", mesh.name}}});
    add_hint(MessageId::wide_too_much_work);
  }
  if (yours.nodes == 0) {
    add_failure({MessageId::wide_failure_nodes_not_counted, {}});
  } else if (yours.rays_nodes_under_reported > 0) {
    add_hint(MessageId::wide_nodes_under_counted);
    add_failure({MessageId::bvh_failure_nodes_under_reported,
                 {{"rays", gtest_text(yours.rays_nodes_under_reported)}, {"total", gtest_text(rays.size())}}});
  }
  if (yours.reported_tests != yours.tests) {
    add_hint(MessageId::bvh_stats_not_counted);
    add_failure({MessageId::bvh_failure_stats,
                 {{"counted", stream_text(double(yours.reported_tests) / double(rays.size()))},
                  {"tested", stream_text(per_ray)}}});
  }
}

}  // namespace
}  // namespace raylab::grading
