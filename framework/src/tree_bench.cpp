// raylab bench: the student's trees side by side on one scene (raylab/tree_bench.h).
#include "raylab/tree_bench.h"

#include "tree_answers.h"

#include "raylab/error.h"
#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/stages/01_camera_rays.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <thread>

namespace raylab {
namespace {

using Clock = std::chrono::steady_clock;

#if defined(__clang__)
constexpr const char* kCompiler = "clang " __clang_version__;
#elif defined(__GNUC__)
constexpr const char* kCompiler = "GCC " __VERSION__;
#else
constexpr const char* kCompiler = "another compiler";
#endif

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The rows' file beside the scene: <scene's folder>/reference_bench.json.
std::filesystem::path reference_file_of(const std::string& scene_path) {
  return std::filesystem::path(scene_path).parent_path() / "reference_bench.json";
}

nlohmann::json row_json(const TreeBenchRow& row) {
  return {{"tree", row.tree},
          {"not_used", row.not_used},
          {"build_ms", row.build_ms},
          {"tree_kb", row.tree_kb},
          {"rays", row.rays},
          {"closest_mrays", row.closest_mrays},
          {"any_mrays", row.any_mrays},
          {"closest_nodes", row.closest_nodes},
          {"closest_primitives", row.closest_primitives},
          {"any_nodes", row.any_nodes},
          {"any_primitives", row.any_primitives},
          {"wrong", row.wrong},
          {"checked", row.checked}};
}

TreeBenchRow row_of(const nlohmann::json& json) {
  TreeBenchRow row;
  row.tree = json.at("tree").get<std::string>();
  row.not_used = json.value("not_used", "");
  row.build_ms = json.value("build_ms", 0.0);
  row.tree_kb = json.value("tree_kb", 0.0);
  row.rays = json.value("rays", std::uint64_t{0});
  row.closest_mrays = json.value("closest_mrays", 0.0);
  row.any_mrays = json.value("any_mrays", 0.0);
  row.closest_nodes = json.value("closest_nodes", 0.0);
  row.closest_primitives = json.value("closest_primitives", 0.0);
  row.any_nodes = json.value("any_nodes", 0.0);
  row.any_primitives = json.value("any_primitives", 0.0);
  row.wrong = json.value("wrong", std::uint64_t{0});
  row.checked = json.value("checked", std::uint64_t{0});
  return row;
}

void print_row(const std::string& who, const TreeBenchRow& row) {
  if (!row.not_used.empty()) {
    std::printf("%-10s %-10s %s\n", who.c_str(), row.tree.c_str(), row.not_used.c_str());
    return;
  }
  const auto per_ray = [](double value) {
    char text[32];
    if (value > 0.0)
      std::snprintf(text, sizeof text, "%.1f", value);
    else
      std::snprintf(text, sizeof text, "-");
    return std::string(text);
  };
  const std::string wrong = std::to_string(row.wrong) + " of " + std::to_string(row.checked);
  std::printf("%-10s %-10s %9.1f %8.1f %9.2f %7s %7s %9.2f %7s %7s  %s\n", who.c_str(), row.tree.c_str(), row.build_ms,
              row.tree_kb, row.closest_mrays, per_ray(row.closest_nodes).c_str(), per_ray(row.closest_primitives).c_str(),
              row.any_mrays, per_ray(row.any_nodes).c_str(), per_ray(row.any_primitives).c_str(), wrong.c_str());
}

}  // namespace

std::vector<TreeBenchRow> bench_trees(const Scene& scene, const TreeBenchOptions& options) {
  // The camera rays, through the pixel centres of a width x height picture of the scene's view.
  Camera camera = scene.camera;
  camera.width = options.width;
  camera.height = options.height;
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(camera.width) * camera.height);
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) rays.push_back(generate_camera_ray(camera, x, y, glm::vec2(0.5f)));

  // The answers to check each tree's against: testing every primitive, on every `check_step`th
  // ray (about 50 million tests in all), closest hit and any hit.
  TracingFunctions without_trees;
  without_trees.tree = StageTree::None;
  const SceneGeometry every_primitive(scene, Acceleration::BruteForce, TriangleTest::MollerTrumbore, without_trees);
  const double all_tests = static_cast<double>(rays.size()) *
                           static_cast<double>(std::max<std::size_t>(1, every_primitive.triangle_count() + every_primitive.sphere_count()));
  const auto check_step = static_cast<std::size_t>(std::max(1.0, all_tests / 5e7));
  std::vector<std::optional<float>> expected_t;
  std::vector<bool> expected_blocked;
  for (std::size_t i = 0; i < rays.size(); i += check_step) {
    const std::optional<SurfaceHit> hit = every_primitive.intersect(rays[i]);
    expected_t.push_back(hit ? std::optional<float>(hit->t_hit) : std::nullopt);
    expected_blocked.push_back(every_primitive.occluded(rays[i]));
  }

  std::vector<TreeBenchRow> rows;
  const auto measure = [&](TreeBenchRow row, const TracingFunctions& tracing, std::optional<StageTree> wanted) {
    try {
      const Clock::time_point start = Clock::now();
      const SceneGeometry geometry(scene, Acceleration::Bvh, TriangleTest::MollerTrumbore, tracing);
      row.build_ms = seconds_since(start) * 1e3;
      row.tree_kb = static_cast<double>(geometry.tree_bytes()) / 1024.0;
      if (wanted && geometry.tree_choice().used != *wanted) {
        const SceneGeometry::TreeChoice& choice = geometry.tree_choice();
        row.not_used = choice.small_sets_only       ? "no tree: every set of primitives in the scene is small (4 or fewer)"
                       : !choice.stub_stage.empty() ? "stage " + choice.stub_stage + " is not written yet"
                                                    : "no mesh large enough for a tree of its own (more than 4 triangles)";
        rows.push_back(row);
        return;
      }
      // Every primitive for every ray is slow: a share of the rays, about 50 million tests.
      const std::size_t step = wanted == StageTree::None ? check_step : 1;
      std::size_t hits = 0, count = 0;
      (void)SceneGeometry::take_thread_work();
      Clock::time_point begin = Clock::now();
      for (std::size_t i = 0; i < rays.size(); i += step, ++count) hits += geometry.intersect(rays[i]) ? 1 : 0;
      const double closest_seconds = seconds_since(begin);
      const SceneGeometry::Work closest = SceneGeometry::take_thread_work();
      begin = Clock::now();
      for (std::size_t i = 0; i < rays.size(); i += step) hits += geometry.occluded(rays[i]) ? 1 : 0;
      const double any_seconds = seconds_since(begin);
      const SceneGeometry::Work any = SceneGeometry::take_thread_work();
      (void)hits;
      const auto n = static_cast<double>(std::max<std::size_t>(1, count));
      row.rays = count;
      row.closest_mrays = n / std::max(closest_seconds, 1e-9) * 1e-6;
      row.any_mrays = n / std::max(any_seconds, 1e-9) * 1e-6;
      row.closest_nodes = static_cast<double>(closest.nodes) / n;
      row.closest_primitives = static_cast<double>(closest.primitives) / n;
      row.any_nodes = static_cast<double>(any.nodes) / n;
      row.any_primitives = static_cast<double>(any.primitives) / n;
      // Its answers against testing every primitive (not timed).
      for (std::size_t i = 0, k = 0; i < rays.size(); i += check_step, ++k) {
        const std::optional<SurfaceHit> hit = geometry.intersect(rays[i]);
        const bool same_closest =
            same_closest_t(hit ? std::optional<float>(hit->t_hit) : std::nullopt, expected_t[k]);
        if (!same_closest || geometry.occluded(rays[i]) != expected_blocked[k]) ++row.wrong;
        ++row.checked;
      }
      (void)SceneGeometry::take_thread_work();
    } catch (const NotImplemented&) {
      throw;
    } catch (const std::exception& error) {
      row.not_used = error.what();
    }
    rows.push_back(row);
  };
  const auto measure_tree = [&](StageTree tree) {
    TracingFunctions tracing;
    tracing.tree = tree;
    TreeBenchRow row;
    row.tree = stage_tree_name(tree);
    measure(row, tracing, tree);
  };
  for (const StageTree tree : kStageBuiltTrees) measure_tree(tree);
  measure_tree(StageTree::None);
  if (options.own_tree) {
    TracingFunctions tracing;
    tracing.own_tree = options.own_tree;
    TreeBenchRow row;
    row.tree = "reference";
    measure(row, tracing, std::nullopt);
  }
  return rows;
}

int run_tree_bench(const TreeBenchOptions& options) {
  const Scene scene = load_scene(options.scene_path);
  const std::vector<TreeBenchRow> rows = bench_trees(scene, options);
  std::printf("%s: %dx%d camera rays, one thread; per ray: nodes whose boxes were tested, primitives tested\n",
              options.scene_path.c_str(), options.width, options.height);
  std::printf("%-10s %-10s %9s %8s %9s %7s %7s %9s %7s %7s  %s\n", "", "tree", "build ms", "memory", "closest", "nodes",
              "prims", "any hit", "nodes", "prims", "wrong answers");
  std::printf("%-10s %-10s %9s %8s %9s %7s %7s %9s %7s %7s  %s\n", "", "", "", "KiB", "Mrays/s", "", "", "Mrays/s", "", "",
              "(against every primitive)");
  const char* who = options.reference_program ? "reference" : "yours";
  for (const TreeBenchRow& row : rows) print_row(who, row);

  const std::filesystem::path file = reference_file_of(options.scene_path);
  const std::string scene_name = std::filesystem::path(options.scene_path).filename().string();
  nlohmann::json saved = nlohmann::json::object();
  if (std::ifstream in(file); in) {
    try {
      saved = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception&) {
      saved = nlohmann::json::object();
    }
  }
  if (options.save_reference) {
    if (!options.reference_program) throw UsageError("--save-reference: only raylab-reference writes the reference's figures");
    nlohmann::json entry = {{"width", options.width}, {"height", options.height}, {"rows", nlohmann::json::array()}};
    for (const TreeBenchRow& row : rows) entry["rows"].push_back(row_json(row));
    saved["scenes"][scene_name] = entry;
    saved["machine"] = std::to_string(std::thread::hardware_concurrency()) + " cores, compiled by " + kCompiler;
    std::ofstream out(file);
    out << saved.dump(2) << "\n";
    if (!out) throw std::runtime_error("cannot write " + file.string());
    std::printf("saved as the reference's figures for %s in %s\n", scene_name.c_str(), file.string().c_str());
  } else if (!options.reference_program && saved.contains("scenes") && saved["scenes"].contains(scene_name)) {
    const nlohmann::json& entry = saved["scenes"][scene_name];
    std::printf("the reference's, from %s (%dx%d rays, %s):\n", file.string().c_str(), entry.value("width", 0),
                entry.value("height", 0), saved.value("machine", "another machine").c_str());
    for (const nlohmann::json& row : entry.at("rows")) print_row("reference", row_of(row));
  }
  return 0;
}

}  // namespace raylab
