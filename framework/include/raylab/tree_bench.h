// `raylab bench SCENE`: the student's own trees side by side on one scene. For each of --accel
// median, sah, wide, kdtree and none: the time to build it and its memory, and closest-hit and any-hit queries of the
// scene's camera rays on one thread, with the work per ray (nodes whose boxes were tested,
// primitives tested), and how many of its answers differ from testing every primitive. Beside
// them, the reference's figures for the same scene, from
// scenes/reference_bench.json (written by `raylab-reference bench SCENE --save-reference`: the
// reference's code of each tree, traced as a student's program traces the student's, and the
// reference's own fastest tree).
#pragma once

#include "raylab/geometry.h"
#include "raylab/scene.h"

#include <string>
#include <vector>

namespace raylab {

struct TreeBenchOptions {
  std::string scene_path;
  int width = 320, height = 240;  // the camera rays: one through each pixel's centre
  bool reference_program = false;  // raylab-reference
  TriangleTreeBuilder own_tree = nullptr;  // the program's own tree (TracingFunctions::own_tree): a row "reference"
  bool save_reference = false;  // write the rows into scenes/reference_bench.json (reference only)
};

// One tree's row.
struct TreeBenchRow {
  std::string tree;          // "median", "sah", "wide", "kdtree", "none", or "reference"
  std::string not_used;      // why it could not be measured ("stage 05c_wide_bvh is not written yet"), or ""
  double build_ms = 0.0;
  double tree_kb = 0.0;      // the trees' memory: nodes, primitive orders, leaf lists (SceneGeometry::tree_bytes)
  std::uint64_t rays = 0;    // of each kind of query
  double closest_mrays = 0.0, any_mrays = 0.0;  // millions of queries per second
  double closest_nodes = 0.0, closest_primitives = 0.0;  // per ray (0 where not counted)
  double any_nodes = 0.0, any_primitives = 0.0;
  // Of `checked` rays (every ray, or a share where testing every primitive would be slow), those
  // whose closest or any hit differs from testing every primitive.
  std::uint64_t wrong = 0, checked = 0;
};

std::vector<TreeBenchRow> bench_trees(const Scene& scene, const TreeBenchOptions& options);
int run_tree_bench(const TreeBenchOptions& options);

}  // namespace raylab
