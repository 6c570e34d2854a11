#include "bvh_support.h"
#include "kit_folders.h"

#include "04_box_calls.h"
#include "05_bvh_calls.h"
#include "grader_geometry.h"
#include "grading.h"

#include "raylab/scene_loader.h"
#include "raylab/stages/04_box.h"
#include "raylab/testkit/random_values.h"
#include "raylab/testkit/triangles.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace raylab::grading {
namespace {

// The grader's own test (grader_geometry.h) on the mesh's triangles.
std::optional<float> test_triangle(const TestMesh& mesh, const Ray& ray, std::uint32_t primitive) {
  return grader_triangle_test(const_cast<std::vector<std::array<glm::vec3, 3>>*>(&mesh.triangles), ray, primitive);
}


std::vector<TestMesh> make_meshes() {
  std::vector<TestMesh> meshes;
  const TriangleMesh bunny = load_obj_mesh(std::string(kit_source_folder()) + "/scenes/bunny.obj");
  std::vector<std::array<glm::vec3, 3>> triangles;
  for (std::size_t i = 0; i + 2 < bunny.indices.size(); i += 3)
    triangles.push_back({bunny.positions[bunny.indices[i]], bunny.positions[bunny.indices[i + 1]],
                         bunny.positions[bunny.indices[i + 2]]});
  meshes.push_back(make_test_mesh(MessageId::bvh_mesh_bunny, triangles));

  Pcg32 random(505, testkit::stream_of("bvh triangle soup"));
  triangles.clear();
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 center = testkit::random_vec3(random, -10, 10);
    triangles.push_back({center + testkit::random_vec3(random, -1, 1), center + testkit::random_vec3(random, -1, 1), center + testkit::random_vec3(random, -1, 1)});
  }
  meshes.push_back(make_test_mesh(MessageId::bvh_mesh_soup, triangles));

  triangles.clear();
  for (int z = 0; z < 20; ++z)
    for (int x = 0; x < 20; ++x) {
      const glm::vec3 a(x, 0, z), b(x + 1, 0, z), c(x + 1, 0, z + 1), d(x, 0, z + 1);
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
  meshes.push_back(make_test_mesh(MessageId::bvh_mesh_flat_grid, triangles));

  triangles.assign(64, {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)});
  meshes.push_back(make_test_mesh(MessageId::bvh_mesh_copies, triangles));

  // Large triangles that all overlap, each moved a little: every split leaves both children
  // about as large as the node, so the SAH prefers one leaf of all 100 -- which must still be
  // split down to max_leaf_size.
  triangles.clear();
  for (int i = 0; i < 100; ++i) {
    const glm::vec3 shift = 0.01f * testkit::random_vec3(random, -1, 1);
    triangles.push_back({glm::vec3(-5, -5, 0) + shift, glm::vec3(5, -5, 1) + shift, glm::vec3(0, 5, -1) + shift});
  }
  meshes.push_back(make_test_mesh(MessageId::bvh_mesh_overlapping, triangles));
  return meshes;
}

}  // namespace

TestMesh make_test_mesh(Message name, std::vector<std::array<glm::vec3, 3>> triangles) {
  TestMesh mesh{std::move(name), std::move(triangles), {}};
  for (const auto& t : mesh.triangles) {
    Bounds3 box;
    for (const glm::vec3& corner : t) box.extend(corner);
    mesh.bounds.push_back(box);
  }
  return mesh;
}

const std::vector<TestMesh>& bvh_test_meshes() {
  static const std::vector<TestMesh> meshes = make_meshes();
  return meshes;
}

PrimitiveIntersector intersector_for(const TestMesh& mesh) {
  return PrimitiveIntersector{grader_triangle_test, const_cast<std::vector<std::array<glm::vec3, 3>>*>(&mesh.triangles)};
}

const TestMesh& work_test_mesh() {
  static const TestMesh mesh = [] {
    std::random_device entropy;
    Pcg32 random((std::uint64_t(entropy()) << 32) | entropy(), testkit::stream_of("bvh work mesh"));
    const glm::vec3 axis = testkit::random_unit_vector(random);
    const float angle = float(testkit::random_double(random, 0.0, 2.0 * kPi));
    const float scale = float(testkit::random_double(random, 0.5, 2.0));
    const glm::vec3 shift = testkit::random_vec3(random, -5, 5);
    const glm::mat3 turn = glm::mat3_cast(glm::angleAxis(angle, axis));
    std::vector<std::array<glm::vec3, 3>> triangles = bvh_test_meshes().front().triangles;
    for (auto& triangle : triangles)
      for (glm::vec3& corner : triangle) corner = scale * (turn * corner) + shift;
    return make_test_mesh(MessageId::bvh_mesh_bunny_moved, std::move(triangles));
  }();
  return mesh;
}

std::optional<BvhHit> brute_force_closest(const TestMesh& mesh, const Ray& ray) {
  return testkit::brute_force_hit(intersector_for(mesh), static_cast<std::uint32_t>(mesh.triangles.size()), ray);
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
    else if (children_in_range(bvh, node)) counts[i] = counts[node.first_index] + counts[node.first_index + 1];
  }
  return counts;
}

namespace {

// Where the ray [t_min, infinity) enters `box` grown by a small margin (double precision),
// or nullopt when it misses: the grader's own slab test, conservative so that a correct
// traversal's leaves are never counted as missed.
std::optional<double> box_entry(const Ray& ray, const Bounds3& box) {
  double t_enter = ray.t_min, t_exit = kInfinity;
  for (int axis = 0; axis < 3; ++axis) {
    const double margin = 1e-5 * (1.0 + std::fabs(double(box.min[axis])) + std::fabs(double(box.max[axis])));
    const double low = double(box.min[axis]) - margin, high = double(box.max[axis]) + margin;
    const double origin = ray.origin[axis], direction = ray.direction[axis];
    if (direction == 0.0) {
      if (origin < low || origin > high) return std::nullopt;
      continue;
    }
    double t_near = (low - origin) / direction, t_far = (high - origin) / direction;
    if (t_near > t_far) std::swap(t_near, t_far);
    t_enter = std::max(t_enter, t_near);
    t_exit = std::min(t_exit, t_far);
    if (t_enter > t_exit) return std::nullopt;
  }
  return t_enter;
}

// The context of the counting intersector: the tree's shape, and what one ray has seen.
class WorkProbe {
 public:
  WorkProbe(const Bvh& bvh, const TestMesh& mesh) : bvh_(bvh), mesh_(mesh) {
    leaf_of_primitive_.assign(mesh.triangles.size(), 0);
    parent_.assign(bvh.nodes.size(), kNone);
    first_seen_.assign(bvh.nodes.size(), false);
    for (std::uint32_t i = 0; i < bvh.nodes.size(); ++i) {
      const BvhNode& node = bvh.nodes[i];
      if (node.is_leaf()) {
        for (std::uint32_t k = 0; k < node.primitive_count; ++k) leaf_of_primitive_[bvh.primitive_order[node.first_index + k]] = i;
      } else {
        parent_[node.first_index] = parent_[node.first_index + 1] = i;
      }
    }
  }

  PrimitiveIntersector intersector() { return PrimitiveIntersector{&WorkProbe::test, this}; }

  void start_ray(const Ray& ray) {
    for (std::uint32_t node : marked_) first_seen_[node] = false;
    marked_.clear();
    ray_ = ray;
    closest_reported_ = kInfinity;
    beyond_a_hit_ = false;
    after_a_hit_ = false;
    last_leaf_ = kNone;
    ++work.rays;
  }
  void end_ray(const BvhTraversalStats& stats) {
    // marked_ holds this ray's tested leaves and all their ancestors: a traversal from the root
    // visited each of them, so a count below theirs is false.
    work.nodes_implied += marked_.size();
    if (stats.nodes_visited < marked_.size()) ++work.rays_nodes_under_reported;
    work.nodes_visited += stats.nodes_visited;
    work.primitives_counted += stats.primitives_tested;
    work.rays_beyond_a_hit += beyond_a_hit_;
    work.rays_after_a_hit += after_a_hit_;
  }

  TraversalWork work;

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  static std::optional<float> test(void* context, const Ray& ray, std::uint32_t primitive) {
    WorkProbe& probe = *static_cast<WorkProbe*>(context);
    ++probe.work.primitives_tested;
    if (probe.closest_reported_ < kInfinity) {
      ++probe.work.calls_after_a_hit;
      probe.after_a_hit_ = true;
    }
    if (ray.t_max > probe.closest_reported_) {
      ++probe.work.calls_beyond_a_hit;
      probe.beyond_a_hit_ = true;
    }
    if (primitive < probe.leaf_of_primitive_.size()) probe.entered(probe.leaf_of_primitive_[primitive]);
    const std::optional<float> t = intersector_for(probe.mesh_).test(intersector_for(probe.mesh_).context, ray, primitive);
    if (t) probe.closest_reported_ = std::min(probe.closest_reported_, *t);
    return t;
  }

  // The first test in `leaf` on this ray: where its box is, and which child of the lowest
  // ancestor already entered the traversal went into first.
  void entered(std::uint32_t leaf) {
    if (leaf == last_leaf_) return;
    last_leaf_ = leaf;
    if (first_seen_[leaf]) return;
    ++work.leaves_entered;
    const std::optional<double> entry = box_entry(ray_, bvh_.nodes[leaf].bounds);
    if (!entry) ++work.leaves_missed_by_ray;
    else if (*entry > double(closest_reported_) + 1e-4 * (1.0 + std::fabs(double(closest_reported_)))) ++work.leaves_beyond_hit;
    std::uint32_t node = leaf;
    mark(node);
    while (parent_[node] != kNone) {
      const std::uint32_t parent = parent_[node];
      if (first_seen_[parent]) {
        const BvhNode& inner = bvh_.nodes[parent];
        const std::uint32_t sibling = node == inner.first_index ? inner.first_index + 1 : inner.first_index;
        // The same rule as the handout: the second child is the nearer one when the ray goes
        // down split_axis (a -0 component counts as negative).
        const bool second_is_near = std::signbit(ray_.direction[inner.split_axis % 3]);
        const std::uint32_t near_child = inner.first_index + (second_is_near ? 1u : 0u);
        if (sibling == near_child) ++work.near_child_first;
        else ++work.far_child_first;
        return;
      }
      mark(parent);
      node = parent;
    }
  }
  void mark(std::uint32_t node) {
    first_seen_[node] = true;
    marked_.push_back(node);
  }

  const Bvh& bvh_;
  const TestMesh& mesh_;
  std::vector<std::uint32_t> leaf_of_primitive_, parent_, marked_;
  std::vector<bool> first_seen_;
  Ray ray_;
  float closest_reported_ = kInfinity;
  bool beyond_a_hit_ = false;
  bool after_a_hit_ = false;
  std::uint32_t last_leaf_ = kNone;
};

// One ray's traversal as the grader runs it: the reference's algorithm with the stage server's box
// test (the grader's own when stage 05 is graded: stages.json "grader_versions"), the one your
// traversal runs, so that the work test judges the traversal alone. It goes a box test at a time, so that the box
// tests of many rays can go to the stage server in one request (reference_traversal_work).
class GraderTraversal {
 public:
  GraderTraversal(const Bvh& bvh, const Ray& ray)
      : bvh_(&bvh), search_(ray), ray_direction_inverse_(ray_direction_inverse_of(ray)) {}

  // The node whose box is tested next (counted as visited), or nullopt when the traversal is done.
  std::optional<std::uint32_t> next(BvhTraversalStats& stats) {
    if (stack_.empty()) return std::nullopt;
    const std::uint32_t node = stack_.back();
    stack_.pop_back();
    ++stats.nodes_visited;
    return node;
  }
  // The arguments of the box test of `node`: the ray with t_max lowered to the closest hit so far.
  BoxTestArguments box_test(std::uint32_t node) const {
    return {search_, ray_direction_inverse_, bvh_->nodes[node].bounds};
  }
  // The box test of `node` answered: if its box is hit, a leaf's primitives are tested, an inner
  // node's children are visited, the nearer one first.
  void enter(std::uint32_t node, bool box_hit, const PrimitiveIntersector& intersector, BvhTraversalStats& stats) {
    if (!box_hit) return;
    const BvhNode& entered = bvh_->nodes[node];
    if (entered.is_leaf()) {
      for (std::uint32_t i = entered.first_index; i < entered.first_index + entered.primitive_count; ++i) {
        ++stats.primitives_tested;
        if (const std::optional<float> t = intersector.test(intersector.context, search_, bvh_->primitive_order[i]))
          search_.t_max = *t;
      }
      return;
    }
    const bool second_is_near = std::signbit(search_.direction[entered.split_axis % 3]);
    stack_.push_back(entered.first_index + (second_is_near ? 0u : 1u));  // the far child, later
    stack_.push_back(entered.first_index + (second_is_near ? 1u : 0u));  // the near child, next
  }

 private:
  const Bvh* bvh_;
  Ray search_;
  glm::vec3 ray_direction_inverse_;
  std::vector<std::uint32_t> stack_{0};
};

void build_grader_node(Bvh& bvh, const std::vector<Bounds3>& bounds, std::uint32_t node_index, std::uint32_t begin,
                       std::uint32_t end, std::uint32_t max_leaf_size) {
  Bounds3 box;
  for (std::uint32_t i = begin; i < end; ++i) box.extend(bounds[bvh.primitive_order[i]]);
  bvh.nodes[node_index].bounds = box;
  if (end - begin <= max_leaf_size) {
    bvh.nodes[node_index].first_index = begin;
    bvh.nodes[node_index].primitive_count = static_cast<std::uint16_t>(end - begin);
    return;
  }
  const int axis = box.longest_axis();
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(bvh.primitive_order.begin() + begin, bvh.primitive_order.begin() + middle,
                   bvh.primitive_order.begin() + end, [&](std::uint32_t a, std::uint32_t b) {
                     const float ca = bounds[a].centroid()[axis], cb = bounds[b].centroid()[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  const auto first_child = static_cast<std::uint32_t>(bvh.nodes.size());
  bvh.nodes.resize(bvh.nodes.size() + 2);
  bvh.nodes[node_index].first_index = first_child;
  bvh.nodes[node_index].split_axis = static_cast<std::uint8_t>(axis);
  build_grader_node(bvh, bounds, first_child, begin, middle, max_leaf_size);
  build_grader_node(bvh, bounds, first_child + 1, middle, end, max_leaf_size);
}

}  // namespace

Bvh grader_median_tree(const std::vector<Bounds3>& bounds, int max_leaf_size) {
  Bvh bvh;
  bvh.primitive_order.resize(bounds.size());
  for (std::uint32_t i = 0; i < bounds.size(); ++i) bvh.primitive_order[i] = i;
  if (bounds.empty()) return bvh;
  bvh.nodes.resize(1);
  build_grader_node(bvh, bounds, 0, 0, static_cast<std::uint32_t>(bounds.size()), static_cast<std::uint32_t>(max_leaf_size));
  return bvh;
}

TraversalWork student_traversal_work(const Bvh& bvh, const TestMesh& mesh, const std::vector<Ray>& rays,
                                     bool any_hit) {
  WorkProbe probe(bvh, mesh);
  for (const Ray& ray : rays) {
    probe.start_ray(ray);
    BvhTraversalStats stats;
    const std::optional<BvhHit> hit = intersect_bvh(bvh, ray, probe.intersector(), any_hit, stats);
    probe.end_ray(stats);
    const std::optional<BvhHit> expected = brute_force_closest(mesh, ray);
    if (hit.has_value() != expected.has_value() || (!any_hit && hit && hit->t_hit != expected->t_hit))
      ++probe.work.rays_answered_wrong;
  }
  return probe.work;
}

TraversalWork reference_traversal_work(const Bvh& bvh, const TestMesh& mesh, const std::vector<Ray>& rays) {
  // 1. Every ray's traversal at once, a step each per round, the box tests of a round in one
  //    request (a round trip per box test cost more than all the rest of the stage). The answers
  //    are kept, each ray's in order.
  const PrimitiveIntersector grader_test = intersector_for(mesh);
  std::vector<GraderTraversal> traversals;
  traversals.reserve(rays.size());
  for (const Ray& ray : rays) traversals.emplace_back(bvh, ray);
  std::vector<std::vector<bool>> box_hits(rays.size());
  std::vector<std::size_t> asking;
  std::vector<std::uint32_t> nodes;
  std::vector<BoxTestArguments> box_tests;
  BvhTraversalStats uncounted;
  for (;;) {
    asking.clear();
    nodes.clear();
    box_tests.clear();
    for (std::size_t r = 0; r < traversals.size(); ++r)
      if (const std::optional<std::uint32_t> node = traversals[r].next(uncounted)) {
        asking.push_back(r);
        nodes.push_back(*node);
        box_tests.push_back(traversals[r].box_test(*node));
      }
    if (asking.empty()) break;
    const std::vector<std::optional<float>> answers = intersect_ray_box_each(box_tests);
    for (std::size_t k = 0; k < asking.size(); ++k) {
      box_hits[asking[k]].push_back(answers[k].has_value());
      traversals[asking[k]].enter(nodes[k], answers[k].has_value(), grader_test, uncounted);
    }
  }
  // 2. Each ray again, alone, with the probe counting its work: the same steps (the probe's
  //    triangle test is the grader's), each box test answered as in 1.
  WorkProbe probe(bvh, mesh);
  for (std::size_t r = 0; r < rays.size(); ++r) {
    probe.start_ray(rays[r]);
    BvhTraversalStats stats;
    GraderTraversal traversal(bvh, rays[r]);
    std::size_t step = 0;
    while (const std::optional<std::uint32_t> node = traversal.next(stats))
      traversal.enter(*node, box_hits[r].at(step++), probe.intersector(), stats);
    probe.end_ray(stats);
  }
  return probe.work;
}

int compare_with_brute_force(const Bvh& bvh, const TestMesh& mesh, const std::vector<Ray>& rays, bool any_hit,
                             const Message& what) {
  return compare_traversal_with_brute_force(intersect_bvh_each(bvh, mesh.triangles, rays, any_hit), true, mesh, rays,
                                            any_hit, what);
}

int compare_traversal_with_brute_force(const std::vector<std::optional<BvhHit>>& answers, bool graders_box_test,
                                       const TestMesh& mesh, const std::vector<Ray>& rays, bool any_hit,
                                       const Message& what) {
  int differences = 0;
  for (std::size_t r = 0; r < rays.size(); ++r) {
    const Ray& ray = rays[r];
    const std::optional<BvhHit> expected = brute_force_closest(mesh, ray);
    const std::optional<BvhHit>& got = answers.at(r);
    bool ok = got.has_value() == expected.has_value();
    if (ok && got && !any_hit) ok = got->t_hit == expected->t_hit;  // same primitive test: exactly equal
    // ... and the primitive is the one hit there (another at exactly the same t, a tie, is as good).
    const auto hit_there = [&](std::uint32_t primitive) {
      return primitive < mesh.triangles.size() && test_triangle(mesh, ray, primitive) == std::optional<float>(got->t_hit);
    };
    bool wrong_primitive = ok && got && !any_hit && got->primitive != expected->primitive && !hit_there(got->primitive);
    ok = ok && !wrong_primitive;
    if (ok && got && any_hit) ok = got->primitive < mesh.triangles.size() && test_triangle(mesh, ray, got->primitive).has_value();
    if (ok) continue;
    if (++differences > 3) continue;
    // any_hit: a primitive that is not hit, at a distance where another one is.
    if (got && any_hit && expected && !hit_there(got->primitive))
      for (std::uint32_t p = 0; p < mesh.triangles.size() && !wrong_primitive; ++p) wrong_primitive = hit_there(p);
    // A real hit of the primitive it names, outside the ray's own interval: the interval was ignored.
    Ray whole_line = ray;
    whole_line.t_min = 0.0f;
    whole_line.t_max = kInfinity;
    const bool outside_interval = got && std::isfinite(got->t_hit) && !(got->t_hit > ray.t_min && got->t_hit < ray.t_max) &&
                                  got->primitive < mesh.triangles.size() &&
                                  test_triangle(mesh, whole_line, got->primitive) == std::optional<float>(got->t_hit);
    const bool zero_component = ray.direction.x == 0 || ray.direction.y == 0 || ray.direction.z == 0;
    if (wrong_primitive)
      add_hint(MessageId::bvh_wrong_primitive);
    else if (outside_interval)
      add_hint(MessageId::bvh_interval_ignored);
    else if (got && expected && got->t_hit > expected->t_hit)
      add_hint(MessageId::bvh_not_closest);
    else if (got && expected)
      add_hint(MessageId::bvh_t_too_close);
    else if (!got && expected) {
      // With the grader's own box test, a dropped hit is the traversal's doing.
      if (!graders_box_test) {
        add_hint(MessageId::bvh_misses_hit_somewhere);  // whose box tests, this comparison cannot tell
      } else if (zero_component) {
        add_hint(MessageId::bvh_misses_zero_component);
      } else {
        add_hint(MessageId::bvh_misses_hit);
      }
    }
    else
      add_hint(MessageId::bvh_false_hit);
    auto hit_of = [](const std::optional<BvhHit>& hit) {
      if (!hit) return Message(MessageId::value_no_hit);
      return Message(MessageId::value_t_primitive,
                     {{"t", std::to_string(hit->t_hit)}, {"primitive", std::to_string(hit->primitive)}});
    };
    add_failure({MessageId::bvh_failure_ray,
                 {{"what", what}, {"mesh", mesh.name}, {"index", std::to_string(r)}, {"ray", ray_text(ray)},
                  {"expected", hit_of(expected)}, {"got", hit_of(got)}}});
  }
  return differences;
}

}  // namespace raylab::grading
