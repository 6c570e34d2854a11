#include "raylab/integrator.h"

namespace raylab {

RenderContext::RenderContext(const Scene& scene_, const SceneGeometry& geometry_, int max_depth_, const Skips& skips_,
                             float roulette_probability_)
    : scene(scene_),
      geometry(geometry_),
      needs(analyse_scene(scene_)),
      lights(scene_),
      max_depth(max_depth_),
      roulette_probability(roulette_probability_),
      skips(skips_) {}

std::optional<IntegratorKind> integrator_from_name(const std::string& name) {
  if (name == "whitted") return IntegratorKind::Whitted;
  if (name == "direct") return IntegratorKind::DirectLight;
  if (name == "path") return IntegratorKind::Path;
  if (name == "mis") return IntegratorKind::PathMis;
  return std::nullopt;
}

const char* integrator_name(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::Whitted: return "whitted";
    case IntegratorKind::DirectLight: return "direct";
    case IntegratorKind::Path: return "path";
    case IntegratorKind::PathMis: return "mis";
  }
  return "unknown";
}

}  // namespace raylab
