#include "raylab/integrator.h"

#include <exception>

namespace raylab {

RenderContext::RenderContext(const Scene& scene_, const SceneGeometry& geometry_, int max_depth_, const Skips& skips_,
                             RussianRoulette roulette_)
    : scene(scene_),
      geometry(geometry_),
      needs(analyse_scene(scene_)),
      lights(scene_),
      max_depth(max_depth_),
      roulette(roulette_),
      skips(skips_) {}

std::optional<RussianRoulette> RussianRoulette::from_text(const std::string& text) {
  if (text == "auto") return RussianRoulette{1.0f, true};
  std::size_t used = 0;
  float probability = 0.0f;
  try {
    probability = std::stof(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;  // not a number, or out of float's range
  }
  if (used != text.size() || !(probability >= kLeastProbability && probability <= 1.0f)) return std::nullopt;
  return RussianRoulette{probability, false};
}

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
