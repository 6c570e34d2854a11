#include "raylab/trace.h"

#include "trace_text.h"

#include <nlohmann/json.hpp>

#include "raylab/math.h"
#include "raylab/sampler.h"
#include "raylab/stage_table.h"
#include "raylab/stages/01_camera_rays.h"
#include "raylab/stages/02_sphere.h"
#include "raylab/stages/04_box.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace raylab {

using namespace trace_text;

std::string TraceStep::file() const {
  const StageDescription* description = find_stage_description(stage);
  return description && !description->files.empty() ? "assignments/" + std::string(description->files.front())
                                                    : std::string();
}

namespace {

// The exact slab test, in double: the entry t into the closed box within the ray's interval, or
// nullopt; and whether the ray only grazes it (entry and exit within rounding of each other).
struct Slab {
  double enter, exit;
};
Slab exact_slab(const Ray& ray, const Bounds3& box) {
  double enter = ray.t_min, exit = ray.t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const double origin = ray.origin[axis], direction = ray.direction[axis];
    if (direction == 0.0) {
      if (origin < box.min[axis] || origin > box.max[axis]) return {1.0, 0.0};
      continue;
    }
    double near_t = (box.min[axis] - origin) / direction, far_t = (box.max[axis] - origin) / direction;
    if (near_t > far_t) std::swap(near_t, far_t);
    enter = std::max(enter, near_t);
    exit = std::min(exit, far_t);
  }
  return {enter, exit};
}
std::optional<float> exact_box_entry(const Ray& ray, const Bounds3& box) {
  const Slab slab = exact_slab(ray, box);
  if (!(slab.enter <= slab.exit)) return std::nullopt;
  return static_cast<float>(slab.enter);
}
// A box of some thickness on every axis: a flat one (a wall's) is crossed at one t, and the
// closed box's contract says that is a hit.
bool exact_box_grazes(const Ray& ray, const Bounds3& box) {
  const glm::vec3 extent = box.extent();
  if (!(extent.x > 0.0f && extent.y > 0.0f && extent.z > 0.0f)) return false;
  const Slab slab = exact_slab(ray, box);
  return std::fabs(slab.exit - slab.enter) <= 1e-4 * std::max({1.0, std::fabs(slab.enter), std::fabs(slab.exit)});
}

}  // namespace

float miss_length(const Scene& scene) {
  Bounds3 bounds;
  for (const Sphere& sphere : scene.spheres) {
    bounds.extend(sphere.center - glm::vec3(sphere.radius));
    bounds.extend(sphere.center + glm::vec3(sphere.radius));
  }
  for (const TriangleMesh& mesh : scene.meshes)
    for (const glm::vec3& position : mesh.positions) bounds.extend(position);
  bounds.extend(scene.camera.position);
  const float diagonal = glm::length(bounds.extent());
  return std::isfinite(diagonal) && diagonal > 0.0f ? diagonal : 1.0f;
}

int PixelTrace::first_disagreement() const {
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (!steps[i].agrees) return static_cast<int>(i);
  return -1;
}

PixelTrace trace_pixel(const Scene& scene, int x, int y, const TraceSettings& settings,
                       const TracingFunctions& contract) {
  const Camera& camera = scene.camera;
  if (x < 0 || y < 0 || x >= camera.width || y >= camera.height)
    throw std::invalid_argument("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                                std::to_string(camera.width) + "x" + std::to_string(camera.height) + " image");
  if (settings.sample < 0 || settings.sample >= settings.samples_per_pixel)
    throw std::invalid_argument("sample " + std::to_string(settings.sample) + " is outside the pixel's " +
                                std::to_string(settings.samples_per_pixel) + " (from 0 to " +
                                std::to_string(settings.samples_per_pixel - 1) + ": --spp sets how many)");
  PixelTrace trace;
  trace.x = x;
  trace.y = y;
  trace.settings = settings;
  // The sample's random numbers, as the renderer draws them (render.cpp): the point in the pixel
  // first, then the integrator's.
  Sampler sampler(settings.samples_per_pixel, settings.seed);
  sampler.start_pixel_sample(x, y, settings.sample);
  const glm::vec2 position_in_pixel = sampler.get_pixel_2d();
  trace.position_in_pixel = position_in_pixel;

  // The steps' words in the trace's language.
  const Words words{settings.chinese};
  const std::string not_written = words("not written yet", "尚未编写");
  const auto mesh_name = [&](std::size_t m) { return mesh_text(scene, m); };
  const auto your_camera_ray = settings.yours.camera_ray ? settings.yours.camera_ray : generate_camera_ray;
  const auto your_sphere_test = settings.yours.sphere ? settings.yours.sphere : intersect_ray_sphere;
  const auto your_triangle_test = settings.yours.triangle ? settings.yours.triangle : intersect_ray_triangle;

  // Stage 01: the camera ray.
  const Ray ray = contract.camera_ray(camera, x, y, position_in_pixel);
  {
    bool stub = false;
    const std::optional<Ray> got = yours([&] { return your_camera_ray(camera, x, y, position_in_pixel); }, stub);
    TraceStep step{"01_camera_rays", "generate_camera_ray",
                   "generate_camera_ray(camera, " + std::to_string(x) + ", " + std::to_string(y) + ", " +
                       text(position_in_pixel) + ")",
                   stub ? not_written : ray_text(words, *got), ray_text(words, ray)};
    step.agrees = !stub && near(got->origin, ray.origin) && near(got->direction, ray.direction);
    trace.steps.push_back(step);
  }

  // Stages 02 and 03 along the contract's ray: every primitive that either answer hits.
  struct Closest {
    float t = kInfinity;
    std::string what;
    std::optional<std::size_t> sphere;  // the primitive: a sphere, else triangle of mesh
    std::size_t mesh = 0, triangle = 0;
  } closest_yours, closest_contract;
  const auto record = [](Closest& closest, const std::optional<float>& t, const std::string& what,
                         std::optional<std::size_t> sphere, std::size_t mesh, std::size_t triangle) {
    if (t && *t < closest.t) closest = {*t, what, sphere, mesh, triangle};
  };
  // A stub is shown once, at its first call; the calls after it are not listed.
  bool sphere_stub_shown = false, triangle_stub_shown = false;
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
    const Sphere& sphere = scene.spheres[i];
    bool stub = false;
    const std::optional<std::optional<float>> got =
        yours([&] { return your_sphere_test(ray, sphere.center, sphere.radius); }, stub);
    const std::optional<float> expected = contract.sphere(ray, sphere.center, sphere.radius);
    const std::string what = words("sphere ", "球 ") + std::to_string(i);
    if (got) record(closest_yours, *got, what, i, 0, 0);
    record(closest_contract, expected, what, i, 0, 0);
    if ((!stub && !*got && !expected) || (stub && sphere_stub_shown)) {
      ++trace.untouched_spheres;
      continue;
    }
    sphere_stub_shown = sphere_stub_shown || stub;
    TraceStep step{"02_sphere", "intersect_ray_sphere", sphere_call_text(words, sphere, i),
                   stub ? not_written : t_text(words, *got), t_text(words, expected)};
    step.agrees = !stub && near(*got, expected);
    trace.steps.push_back(step);
  }
  for_each_triangle(scene, [&](std::size_t m, std::size_t k, const glm::vec3& p0, const glm::vec3& p1,
                               const glm::vec3& p2) {
    bool stub = false;
    const std::optional<std::optional<TriangleHit>> got = yours([&] { return your_triangle_test(ray, p0, p1, p2); }, stub);
    const std::optional<TriangleHit> expected = contract.triangle(ray, p0, p1, p2);
    const std::string what = settings.chinese ? "网格 " + mesh_name(m) + " 的三角形 " + std::to_string(k)
                                              : "triangle " + std::to_string(k) + " of mesh " + mesh_name(m);
    if (got && *got) record(closest_yours, (*got)->t_hit, what, std::nullopt, m, k);
    if (expected) record(closest_contract, expected->t_hit, what, std::nullopt, m, k);
    if ((!stub && !*got && !expected) || (stub && triangle_stub_shown)) {
      ++trace.untouched_triangles;
      return;
    }
    triangle_stub_shown = triangle_stub_shown || stub;
    TraceStep step{"03_triangle", "intersect_ray_triangle", triangle_call_text(words, p0, p1, p2, k, mesh_name(m)),
                   stub ? not_written : triangle_hit_text(words, *got), triangle_hit_text(words, expected)};
    step.agrees = !stub && near(*got, expected);
    trace.steps.push_back(step);
  });

  // The closest hit, as the renderer picks it from the answers above.
  const std::string background = words("nothing: the background", "什么也没有击中：背景");
  const auto closest_text = [&](const Closest& closest) {
    return closest.what.empty() ? background : closest.what + words(" at t = ", "，t = ") + text(closest.t);
  };
  TraceStep closest{"", "", words("the closest hit along the camera ray", "沿相机光线的最近交点"),
                    closest_text(closest_yours), closest_text(closest_contract)};
  closest.agrees = closest_yours.what == closest_contract.what && near(closest_yours.t, closest_contract.t);
  trace.steps.push_back(closest);
  trace.segments.push_back(
      {ray.origin, ray.origin + ray.direction * (closest_yours.what.empty() ? miss_length(scene) : closest_yours.t),
       TraceSegment::Kind::Camera});

  // The trees' nodes from the root down to the leaf that holds the contract's closest hit: the
  // ray enters every one of their boxes (each holds that primitive) before it reaches the hit, so
  // your box test must say so (stage 04); then whether your traversal tested that primitive
  // (stage 05) and how many it tested in all. `trees_agree`: the trees' closest hit is the
  // contract's (then not testing it, on a tie, is fine; else the traversal is marked).
  const auto tree_name = [&](int mesh) {
    return mesh < 0 ? words("the tree over the objects", "物体之上的树")
                    : words("mesh ", "网格 ") + mesh_name(static_cast<std::size_t>(mesh)) + words("'s tree", " 的树");
  };
  // Every leaf your traversal opened along the camera ray: each must be one the ray enters (the
  // exact slab test; a thick box it grazes may go either way), before the closest hit the tests
  // before it had found (stage 05's "skip what lies beyond the closest hit found so far").
  const auto trace_leaves_opened = [&](const SceneGeometry::TreeWalk& walk, const Ray& camera_ray) {
    const SceneGeometry::LeafOpened* missed = nullptr;
    const SceneGeometry::LeafOpened* beyond = nullptr;
    int missed_count = 0, beyond_count = 0;
    double beyond_entry = 0;
    for (const SceneGeometry::LeafOpened& leaf : walk.leaves) {
      const Slab slab = exact_slab(camera_ray, leaf.box);
      const double rounding = 1e-4 * std::max(1.0, std::fabs(slab.enter));
      if (!(slab.enter <= slab.exit)) {
        // Missed by rounding only (a flat box's too, a wall's): a float box test may say either.
        if (slab.enter <= slab.exit + rounding || exact_box_grazes(camera_ray, leaf.box)) continue;
        ++missed_count;
        if (!missed) missed = &leaf;
      } else if (std::isfinite(leaf.closest_before) &&
                 slab.enter > leaf.closest_before + 1e-4 * std::max(1.0, std::fabs(double(leaf.closest_before)))) {
        // (the same rounding as SceneGeometry::walk_to's for a test's t_max beyond a hit)
        ++beyond_count;
        if (!beyond) {
          beyond = &leaf;
          beyond_entry = slab.enter;
        }
      }
    }
    const auto leaf_text = [&](const SceneGeometry::LeafOpened& leaf) {
      return words("node ", "节点 ") + std::to_string(leaf.node) + words(" of ", "，") + tree_name(leaf.mesh) +
             words(", box ", "，包围盒 ") + text(leaf.box.min) + " - " + text(leaf.box.max);
    };
    TraceStep step{"05_bvh", "intersect_bvh",
                   words("the leaves your intersect_bvh opened along the camera ray (a leaf whose primitives it tested)",
                         "你的 intersect_bvh 沿相机光线打开的叶节点（测试了其中图元的叶节点）"),
                   words("opened ", "打开了 ") + std::to_string(walk.leaves.size()) +
                       words(walk.leaves.size() == 1 ? " leaf" : " leaves", " 个叶节点") +
                       (walk.leaves_cut ? words(" (the first ones)", "（只统计了前面的）") : "") + words("; ", "；") +
                       std::to_string(missed_count) + words(" the ray misses, ", " 个光线没有进入，") +
                       std::to_string(beyond_count) +
                       words(" entered beyond a hit already found; ", " 个在已经找到的交点之后才进入；") +
                       std::to_string(walk.tests_beyond_a_hit) +
                       words(" primitive tests given a t_max beyond a hit already found",
                             " 次图元测试得到的 t_max 超过了已经找到的交点"),
                   words("only leaves the ray enters; each test's t_max lowered to the closest hit found so far "
                         "(and a leaf beyond it skipped)",
                         "只打开光线进入的叶节点；每次测试的 t_max 降到目前找到的最近交点（并跳过在它之后的叶节点）"),
                   "", missed_count == 0 && walk.tests_beyond_a_hit == 0};
    if (missed) {
      // Your box test says the ray enters it: the box test's mistake; else the traversal opened a
      // leaf its box test turned away.
      bool stub = false;
      const std::optional<std::optional<float>> got =
          yours([&] { return intersect_ray_box(camera_ray, ray_direction_inverse_of(camera_ray), missed->box); }, stub);
      const bool box_says_enters = !stub && got && got->has_value();
      if (box_says_enters) {
        step.stage = "04_box";
        step.function = "intersect_ray_box";
      }
      step.note = leaf_text(*missed) +
                  (box_says_enters
                       ? words(": the ray misses this box, yet your intersect_ray_box says it enters at t = ",
                               "：光线没有进入这个包围盒，你的 intersect_ray_box 却说它在 t = ") +
                             text(**got) + words("", " 处进入")
                       : words(": the ray misses this box (so does your intersect_ray_box), yet your traversal "
                               "tested its primitives: test a node's box before anything below it",
                               "：光线没有进入这个包围盒（你的 intersect_ray_box 也这么说），你的遍历却测试了其中的图元："
                               "先测试节点的包围盒，再处理它下面的任何东西"));
    } else if (walk.tests_beyond_a_hit > 0) {
      step.note = words("your traversal called intersector.test with t_max = ", "你的遍历调用 intersector.test 时 t_max = ") +
                  text(walk.first_test_beyond_a_hit.first) + words(" after a hit at t = ", "，而之前已经在 t = ") +
                  text(walk.first_test_beyond_a_hit.second) +
                  words(" had been found: lower the ray's t_max to each hit's t", " 处找到了交点：每次击中后把光线的 t_max 降到交点的 t");
    } else if (beyond) {
      // Not a disagreement: more work than needed, which the grader's work test weighs.
      step.note = leaf_text(*beyond) + words(": the ray enters it at t = ", "：光线在 t = ") + text(beyond_entry) +
                  words(", beyond the hit at t = ", " 处才进入它，而之前已经在 t = ") + text(beyond->closest_before) +
                  words(" found before it: work a traversal can skip (a node whose entry is beyond the closest hit, "
                        "and the near child first)",
                        " 处找到了交点：这是遍历可以省去的工作（跳过起点在最近交点之后的节点，并先访问近的子节点）");
    }
    trace.steps.push_back(step);
  };
  const auto trace_tree_path = [&](const SceneGeometry& geometry, const Ray& camera_ray, const Closest& target,
                                   bool trees_agree) {
    const SceneGeometry::TreeWalk walk = geometry.walk_to(camera_ray, target.sphere, target.mesh, target.triangle);
    const glm::vec3 inverse = ray_direction_inverse_of(camera_ray);
    for (const SceneGeometry::TreeNodeOnPath& node : walk.path) {
      const std::string tree = tree_name(node.mesh);
      bool stub = false;
      const std::optional<std::optional<float>> got =
          yours([&] { return intersect_ray_box(camera_ray, inverse, node.box); }, stub);
      const std::optional<float> expected = exact_box_entry(camera_ray, node.box);
      TraceStep step{"04_box", "intersect_ray_box",
                     "intersect_ray_box(ray, 1 / direction, " + text(node.box.min) + " - " + text(node.box.max) +
                         ")   [" + words("node ", "节点 ") + std::to_string(node.node) + words(" of ", "，") + tree +
                         words(", depth ", "，深度 ") + std::to_string(node.depth) + "]",
                     stub ? not_written : (got && *got ? words("enters at t = ", "在 t = ") + text(**got) + words("", " 处进入")
                                                       : words("misses", "没有击中")),
                     expected ? words("enters at t = ", "在 t = ") + text(*expected) + words("", " 处进入") +
                                    words(" (it holds ", "（它包含") + target.what + words(")", "）")
                              : words("misses (it grazes the box)", "没有击中（光线擦过包围盒）")};
      step.agrees = !stub && ((got && *got && expected && near(**got, *expected, 1e-3)) || (!expected && got && !*got));
      // A ray that grazes the box within rounding may be called a hit or a miss.
      if (!step.agrees && !stub && exact_box_grazes(camera_ray, node.box)) step.agrees = true;
      trace.steps.push_back(step);
    }
    if (walk.path.empty()) return;
    trace_leaves_opened(walk, camera_ray);
    TraceStep tested{"05_bvh", "intersect_bvh",
                     words("the primitives your intersect_bvh tested along the camera ray",
                           "你的 intersect_bvh 沿相机光线测试的图元"),
                     (walk.tested ? words("tested ", "测试了") : words("never tested ", "从未测试")) + target.what +
                         words("; ", "；") + std::to_string(walk.primitive_tests) +
                         words(" primitive tests in all", " 次图元测试"),
                     words("tests ", "测试") + target.what + words(" (the closest hit)", "（最近的交点）")};
    // The trees' hit is the contract's: fine, tested or not (another primitive at the same t). Else
    // the traversal lost it, by not testing it or by not keeping it.
    tested.agrees = trees_agree;
    if (!tested.agrees)
      tested.note = walk.tested
                        ? words("your traversal tested it and still returned another hit: look at how intersect_bvh "
                                "keeps the closest hit (and lowers the ray's t_max after each hit)",
                                "你的遍历测试了它，却返回了另一个交点：请检查 intersect_bvh 如何保留最近的交点（以及每次击中后降低光线的 "
                                "t_max）")
                        : words("your traversal never tested it: look at intersect_bvh (which children it visits, and "
                                "when it stops), and at the box tests above",
                                "你的遍历从未测试它：请检查 intersect_bvh（访问哪些子节点，何时停止）以及上面的包围盒测试");
    trace.steps.push_back(tested);
  };

  // The closest hit through your trees (stage 04's box test, stage 05's build and traversal),
  // where the renderer uses them: the same as the tests above give, or a hit the trees lost.
  try {
    const SceneGeometry geometry(scene, Acceleration::Bvh, TriangleTest::MollerTrumbore, settings.yours);
    if (geometry.bvh_count() > 0) {
      const std::optional<SurfaceHit> hit = geometry.intersect(ray);
      const bool contract_hits = !closest_contract.what.empty();
      const auto hit_text = [&](bool hits, float t) { return hits ? "t = " + text(t) : background; };
      // The tree the renderer traces (TracingFunctions::tree; raylab trace --accel): its build,
      // its traversal, and where to look when it loses the hit.
      const StageTree tree = geometry.tree_choice().used;
      // (No stage tree but a program's own over the triangles: in the median tree's words.)
      const StageTreeFacts& facts = stage_tree_facts(tree == StageTree::None ? StageTree::Median : tree);
      const std::string build = facts.build, traversal = facts.traversal;
      const std::string look_at =
          tree == StageTree::Wide     ? "05c_wide_bvh (collapse_bvh4, intersect_bvh4, intersect_ray_box4)"
          : tree == StageTree::KdTree ? "05d_kdtree (build_kdtree, intersect_kdtree)"
          : tree == StageTree::Sah    ? "05b_bvh_sah (build_bvh_sah), 05 (intersect_bvh) and 04 (intersect_ray_box)"
                                      : "05 (build_bvh, intersect_bvh) and stage 04 (intersect_ray_box)";
      const std::string look_at_zh =
          tree == StageTree::Wide     ? "05c_wide_bvh（collapse_bvh4、intersect_bvh4、intersect_ray_box4）"
          : tree == StageTree::KdTree ? "05d_kdtree（build_kdtree、intersect_kdtree）"
          : tree == StageTree::Sah    ? "05b_bvh_sah（build_bvh_sah）、05（intersect_bvh）和 04（intersect_ray_box）"
                                      : "05（build_bvh、intersect_bvh）和阶段 04（intersect_ray_box）";
      TraceStep step{"", "",
                     words("the closest hit through your trees (" + traversal + " on your " + build + "'s tree)",
                           "经过你的树的最近交点（在你的 " + build +
                               (tree == StageTree::Wide ? " 折叠成的树上调用 " : " 建的树上调用 ") + traversal + "）"),
                     hit_text(hit.has_value(), hit ? hit->t_hit : 0.0f), hit_text(contract_hits, closest_contract.t)};
      step.agrees = hit.has_value() == contract_hits && (!hit || near(hit->t_hit, closest_contract.t));
      if (!step.agrees)
        step.note = words("the tests above find the contract's hit, the trees another: look at stage " + look_at,
                          "上面的测试找到了契约的交点，树却找到了另一个：请检查阶段 " + look_at_zh);
      // The nodes on the way to the contract's hit first: a box test or a traversal that loses it
      // is then the first disagreement, rather than the hit it lost. (The binary trees' nodes
      // only: the 4-wide traversal's and the KD-tree's steps are not followed.)
      if (contract_hits && tree != StageTree::Wide && tree != StageTree::KdTree)
        trace_tree_path(geometry, ray, closest_contract, step.agrees);
      trace.steps.push_back(step);
    }
  } catch (const NotImplemented&) {
    // A tree's stub: the renderer tests every primitive then, as the steps above do.
  } catch (const std::exception& e) {
    trace.steps.emplace_back("", "",
                             words("the closest hit through your trees (build_bvh, intersect_bvh, intersect_ray_box)",
                                   "经过你的树的最近交点（build_bvh、intersect_bvh、intersect_ray_box）"),
                             words("threw: ", "抛出了异常：") + e.what(), words("a hit or none", "一个交点或没有交点"), "",
                             false);
  }
  if (settings.integrator != IntegratorKind::Whitted) {
    trace_monte_carlo(scene, ray, sampler, contract, trace);
  } else {
    try {
      trace_whitted(scene, ray, contract, trace);
    } catch (const NotImplemented&) {
      // A stub of your geometry: marked at its first call along the camera ray above.
    } catch (const std::exception& e) {
      // Your trees' build or the camera ray's hit threw: the steps above stand.
      trace.steps.emplace_back("", "", words("the rays after the camera ray", "相机光线之后的光线"),
                               words("threw: ", "抛出了异常：") + e.what(), words("an answer", "一个回答"), "", false);
    }
  }
  return trace;
}

void print_trace(std::ostream& out, const std::string& scene_path, const PixelTrace& trace) {
  const TraceSettings& settings = trace.settings;
  const bool zh = settings.chinese;
  const bool monte_carlo = settings.integrator != IntegratorKind::Whitted;
  const std::string pixel = "(" + std::to_string(trace.x) + ", " + std::to_string(trace.y) + ")";
  const std::string sample = std::to_string(settings.sample), count_of_samples = std::to_string(settings.samples_per_pixel);
  if (zh)
    out << "raylab trace " << scene_path << "：像素 " << pixel << "，" << count_of_samples << " 个样本中的第 " << sample
        << " 个（种子 " << settings.seed << "），穿过像素中的 " << text(trace.position_in_pixel) << "，积分器 "
        << integrator_name(settings.integrator) << "\n"
        << "沿这个样本的" << (monte_carlo ? "路径" : "光线（相机光线及其后的反射、折射和阴影光线）")
        << "列出你的阶段函数的每次调用，旁边是契约对同样的输入和同样的随机数给出的结果（本套件自己的精确版本）。\n"
        << "球和三角形的求交测试使用契约的相机光线" << (monte_carlo ? "" : "；之后的光线从你的交点出发") << "。\n\n";
  else
    out << "raylab trace " << scene_path << ": pixel " << pixel << ", sample " << sample << " of " << count_of_samples
        << " (seed " << settings.seed << "), through " << text(trace.position_in_pixel)
        << " in the pixel, integrator " << integrator_name(settings.integrator) << "\n"
        << (monte_carlo ? "Each call of your stage functions along this sample's path"
                        : "Each call of your stage functions along this sample's rays (the camera ray, and the\n"
                          "reflection, refraction and shadow rays after it)")
        << ", beside what the contract gives for the\n"
        << "same inputs and the same random numbers (the kit's own exact versions). The sphere and triangle tests use\n"
        << "the contract's camera ray" << (monte_carlo ? "" : "; the rays after it start at your hits") << ".\n\n";
  const int first = trace.first_disagreement();
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const TraceStep& step = trace.steps[i];
    out << "  " << i + 1 << ". " << (step.stage.empty() ? "" : (zh ? "阶段 " : "stage ") + step.stage + "  ")
        << step.call << "\n";
    if (!step.yours.empty() || !step.expected.empty())  // (a step that only says what is not traced has neither)
      out << (zh ? "       你的      " : "       yours     ") << step.yours << "\n"
          << (zh ? "       契约      " : "       contract  ") << step.expected << "\n";
    if (!step.note.empty()) out << (zh ? "       说明      " : "       note      ") << step.note << "\n";
    if (static_cast<int>(i) == first) {
      out << (zh ? "       ^ 第一个不一致之处" : "       ^ the first disagreement");
      if (!step.function.empty()) {
        const std::string file = step.file();
        if (zh)
          out << "：你的 " << step.function << (file.empty() ? "" : "（" + file + "）");
        else
          out << ": your " << step.function << (file.empty() ? "" : " (" + file + ")");
      }
      out << "\n";
    } else if (!step.agrees) {
      out << (zh ? "       ^ 也不一致\n" : "       ^ differs too\n");
    }
  }
  const auto count = [](int n, const char* noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); };
  if (trace.untouched_spheres + trace.untouched_triangles > 0) {
    if (zh)
      out << "\n  没有列出：" << trace.untouched_spheres << " 个球和 " << trace.untouched_triangles
          << " 个三角形，你的测试和契约的测试都没有击中它们（或者是桩函数第一次之后的调用）。\n";
    else
      out << "\n  Not listed: " << count(trace.untouched_spheres, "sphere") << " and "
          << count(trace.untouched_triangles, "triangle") << " that neither your tests nor the contract's hit (or a\n"
          << "  stub's calls after its first).\n";
  }
  out << "\n";
  if (zh)
    out << (first < 0 ? std::string(monte_carlo ? "沿这条路径" : "沿这些光线") + "的每个调用都与契约一致。\n"
                      : "从第一个不一致之处开始看：它之后的步骤可能只是因为它才不同。\n");
  else
    out << (first < 0
                ? std::string("Every call agrees with the contract along ") + (monte_carlo ? "this path" : "these rays") + ".\n"
                : "Start at the first disagreement: the steps after it may differ only because of it.\n");
}

void write_trace_json(std::ostream& out, const Camera& camera, const PixelTrace& trace) {
  const bool zh = trace.settings.chinese;
  const bool monte_carlo = trace.settings.integrator != IntegratorKind::Whitted;
  nlohmann::json steps = nlohmann::json::array();
  for (const TraceStep& step : trace.steps)
    steps.push_back({{"stage", step.stage},
                     {"function", step.function},
                     {"file", step.file()},
                     {"call", step.call},
                     {"yours", step.yours},
                     {"expected", step.expected},
                     {"note", step.note},
                     {"agrees", step.agrees}});
  nlohmann::json segments = nlohmann::json::array();
  for (const TraceSegment& segment : trace.segments) {
    // A ray of NaNs (a direction your code made of nothing) has nothing to draw.
    if (!is_finite(segment.from) || !is_finite(segment.to)) continue;
    const std::optional<std::array<glm::vec2, 2>> ends = project_segment_to_raster(camera, segment.from, segment.to);
    if (!ends || !std::isfinite((*ends)[0].x + (*ends)[0].y + (*ends)[1].x + (*ends)[1].y)) continue;
    segments.push_back({{"from", {(*ends)[0].x, (*ends)[0].y}},
                        {"to", {(*ends)[1].x, (*ends)[1].y}},
                        {"kind", segment.kind == TraceSegment::Kind::Camera   ? "camera"
                                 : segment.kind == TraceSegment::Kind::Bounce ? "bounce"
                                                                              : "shadow"}});
  }
  const int first = trace.first_disagreement();
  std::string summary;
  if (first < 0) {
    summary = zh ? std::string(monte_carlo ? "沿这条路径" : "沿这些光线") + "的每个调用都与契约一致。"
                 : std::string("Every call agrees with the contract along ") + (monte_carlo ? "this path" : "these rays") + ".";
  } else {
    const TraceStep& step = trace.steps[static_cast<std::size_t>(first)];
    const std::string where = step.function.empty() ? step.call : step.function;
    summary = zh ? "第一个不一致之处在第 " + std::to_string(first + 1) + " 步：" + where +
                       "。它之后的步骤可能只是因为它才不同。"
                 : "The first disagreement is step " + std::to_string(first + 1) + ", " + where +
                       ": the steps after it may differ only because of it.";
  }
  // Texts may hold bytes a stage printed into a value's words: replaced, never a failed dump.
  out << nlohmann::json{{"ok", true},
                        {"x", trace.x},
                        {"y", trace.y},
                        {"sample", trace.settings.sample},
                        {"steps", steps},
                        {"first_disagreement", first},
                        {"summary", summary},
                        {"segments", segments}}
             .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)
      << "\n";
}

}  // namespace raylab
