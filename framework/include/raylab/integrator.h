// Integrators: the radiance arriving at the camera along one ray, li(ray, sampler), in the
// shape of pbrt-v4's Integrator::Li and Nori's Integrator::Li, without their class trees.
//
// The renderer (render.h) makes one RenderContext per render, then for every pixel sample
// asks li() for the colour along the sample's camera ray. Which integrator runs is a value
// (IntegratorKind), dispatched by one switch per camera ray, not a virtual call per ray.
//
// Adding an integrator (the direct-light and path tracers of the Monte Carlo stages): a
// kind below, a function `glm::vec3 NAME_li(const RenderContext&, const Ray&, Sampler&,
// ShadingStats&)` in its own .cpp, one case in Integrator::li, and its name in
// integrator_from_name (the CLI's --integrator).
#pragma once

#include "raylab/geometry.h"
#include "raylab/lights.h"
#include "raylab/ray.h"
#include "raylab/sampler.h"
#include "raylab/scene.h"
#include "raylab/scene_analysis.h"
#include "raylab/shading.h"

#include <algorithm>
#include <optional>
#include <string>

namespace raylab {

// How a path tracer's paths end at random (docs/09_path.md, section 4). Unbiased either way:
// a path that goes on with probability p is divided by p.
struct RussianRoulette {
  // With by_throughput false: the chance to go on at every bounce, in (0, 1] (1: no roulette;
  // paths end at max_depth only). GAMES101 assignment 7 uses 0.8.
  float probability = 1.0f;
  // True: the chance follows the path's throughput (RenderContext::continue_probability), much
  // as pbrt-v4 does: a path whose weight has fallen is stopped more often, and one that goes on
  // keeps a weight near 1. Fewer samples reach a given error than with a fixed 0.8
  // (docs/performance.md, "Russian roulette by the throughput").
  bool by_throughput = false;

  // "auto": by the throughput; a number in [kLeastProbability, 1]: that fixed probability
  // (smaller ones would weigh the paths that go on by 1000 and more). nullopt otherwise.
  static std::optional<RussianRoulette> from_text(const std::string& text);
  static constexpr float kLeastProbability = 0.001f;
  static bool is_valid_probability(float probability) {
    return probability >= kLeastProbability && probability <= 1.0f;  // false for NaN
  }

  // The chance p, in (0, 1], that a path goes on after its vertex `depth` (0 where the camera
  // ray hit), given its throughput so far. A fixed probability: always it. By the throughput:
  // 1 at the first kFirstDepth vertices, then the throughput's largest channel, kept within
  // [kLeastByThroughput, 1].
  float continue_probability(int depth, const glm::vec3& throughput) const {
    if (!by_throughput) return probability;
    if (depth < kFirstDepth) return 1.0f;
    const float largest = std::max(throughput.x, std::max(throughput.y, throughput.z));
    return std::min(1.0f, std::max(kLeastByThroughput, largest));
  }
  static constexpr int kFirstDepth = 2;
  static constexpr float kLeastByThroughput = 0.05f;
};

// Everything the rays of one render read, and nothing they write: the scene, its geometry
// (the accelerated intersection queries), what the analysis found, and the settings.
struct RenderContext {
  const Scene& scene;
  const SceneGeometry& geometry;
  SceneNeeds needs;
  LightSet lights;    // point lights and emitters (empty: no light sampling)
  int max_depth = 5;  // bounces after the camera ray
  RussianRoulette roulette;  // the path tracer's: ask continue_probability()
  Skips skips;

  // Throws std::invalid_argument for a fixed roulette probability outside
  // [RussianRoulette::kLeastProbability, 1].
  RenderContext(const Scene& scene_, const SceneGeometry& geometry_, int max_depth_, const Skips& skips_,
                RussianRoulette roulette_ = {});

  // The path tracer's Russian roulette (stages 09 and 09b; docs/09_path.md, section 4): the
  // chance p, in (0, 1], that a path goes on after its vertex `depth` (0 where the camera ray
  // hit), given its throughput so far: --roulette P always P; --roulette auto by the throughput
  // (RussianRoulette::continue_probability).
  float continue_probability(int depth, const glm::vec3& throughput) const {
    return roulette.continue_probability(depth, throughput);
  }
};

enum class IntegratorKind {
  Whitted,      // GAMES101 assignment 5: point lights, Phong, mirror and glass; no randomness
  DirectLight,  // emission + light straight from point and area lights at the first diffuse
                // surface (through mirrors and glass), with BSDFs (bsdf.h); no indirect light
  Path,         // GAMES101 assignment 7: Monte Carlo path tracing (stage 09's path_radiance)
  PathMis,      // the same with multiple importance sampling (stage 09b's path_radiance_mis)
};

// "whitted" -> Whitted, "direct" -> DirectLight, "path" -> Path, "mis" -> PathMis; nullopt for an
// unknown name.
std::optional<IntegratorKind> integrator_from_name(const std::string& name);
const char* integrator_name(IntegratorKind kind);

class Integrator {
 public:
  explicit Integrator(IntegratorKind kind = IntegratorKind::Whitted) : kind_(kind) {}

  IntegratorKind kind() const { return kind_; }

  // The radiance (linear RGB) arriving along the camera ray `ray`; the background where it
  // hits nothing. Random numbers come from `sampler` only (started at the pixel sample by
  // the caller); the work done is added to `stats`.
  inline glm::vec3 li(const RenderContext& context, const Ray& ray, Sampler& sampler, ShadingStats& stats) const;

 private:
  IntegratorKind kind_;
};

// Whitted-style ray tracing as in GAMES101 assignment 5 (whitted.cpp). Uses no random numbers.
glm::vec3 whitted_li(const RenderContext& context, const Ray& ray, Sampler& sampler, ShadingStats& stats);

// Direct lighting (direct_light.cpp): per sample, a specular chain up to max_depth, then at
// the first diffuse surface one sample of stage 08's estimate_direct_light (one light, one point
// on it, its shadow ray). Point lights fall off as 1 / d^2 here.
glm::vec3 direct_light_li(const RenderContext& context, const Ray& ray, Sampler& sampler, ShadingStats& stats);

// Path tracing (path.cpp): stage 09's path_radiance, with the camera ray counted.
glm::vec3 path_li(const RenderContext& context, const Ray& ray, Sampler& sampler, ShadingStats& stats);

// Path tracing with multiple importance sampling (path.cpp): stage 09b's path_radiance_mis.
glm::vec3 path_mis_li(const RenderContext& context, const Ray& ray, Sampler& sampler, ShadingStats& stats);

// One switch per camera ray (inline: the renderer calls it for every sample).
inline glm::vec3 Integrator::li(const RenderContext& context, const Ray& ray, Sampler& sampler,
                                ShadingStats& stats) const {
  switch (kind_) {
    case IntegratorKind::Whitted: return whitted_li(context, ray, sampler, stats);
    case IntegratorKind::DirectLight: return direct_light_li(context, ray, sampler, stats);
    case IntegratorKind::Path: return path_li(context, ray, sampler, stats);
    case IntegratorKind::PathMis: return path_mis_li(context, ray, sampler, stats);
  }
  return glm::vec3(0.0f);
}

}  // namespace raylab
