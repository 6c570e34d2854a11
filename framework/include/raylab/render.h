// The renderer: tiles over all cores; each pixel's value depends only on (scene, settings,
// pixel), so any thread count gives bit-identical images.
#pragma once

#include "raylab/geometry.h"
#include "raylab/image.h"
#include "raylab/scene.h"
#include "raylab/shading.h"

#include <cstdint>

namespace raylab {

struct RenderSettings {
  int max_depth = 5;
  int threads = 0;             // 0: every core
  bool show_progress = false;  // progress, ETA and rays/s on stderr
  // What to leave out (shading.h); the same image either way. Changed only to measure.
  Skips skips;
  TriangleTest triangle_test = TriangleTest::MollerTrumbore;  // --watertight: stage 03b's test
};

struct RenderStats {
  double seconds = 0.0;
  ShadingStats work;  // rays by kind, counted (work.rays() in all)
  int threads = 0;
};

// Renders scene.camera's view. Exceptions from stage functions (NotImplemented, ...) stop the
// render and are rethrown here, from the calling thread.
Image render(const Scene& scene, const RenderSettings& settings, RenderStats* stats = nullptr);

}  // namespace raylab
