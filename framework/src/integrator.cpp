#include "raylab/integrator.h"

#include <cctype>
#include <exception>
#include <sstream>
#include <stdexcept>

namespace raylab {

RenderContext::RenderContext(const Scene& scene_, const SceneGeometry& geometry_, int max_depth_, const Skips& skips_,
                             RussianRoulette roulette_)
    : scene(scene_),
      geometry(geometry_),
      needs(analyse_scene(scene_)),
      lights(scene_),
      max_depth(max_depth_),
      roulette(roulette_),
      skips(skips_) {
  if (!roulette.by_throughput && !RussianRoulette::is_valid_probability(roulette.probability)) {
    std::ostringstream message;
    message << "Russian roulette: the probability to go on must be in [" << RussianRoulette::kLeastProbability
            << ", 1], not " << roulette.probability;
    throw std::invalid_argument(message.str());
  }
}

std::optional<RussianRoulette> RussianRoulette::from_text(const std::string& text) {
  if (text == "auto") return RussianRoulette{1.0f, true};
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return std::nullopt;  // as at the end
  std::size_t used = 0;
  float probability = 0.0f;
  try {
    probability = std::stof(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;  // not a number, or out of float's range
  }
  if (used != text.size() || !is_valid_probability(probability)) return std::nullopt;
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
