#include "raylab/integrator.h"

namespace raylab {

RenderContext::RenderContext(const Scene& scene_, const SceneGeometry& geometry_, int max_depth_, const Skips& skips_)
    : scene(scene_), geometry(geometry_), needs(analyse_scene(scene_)), lights(scene_), max_depth(max_depth_), skips(skips_) {}

std::optional<IntegratorKind> integrator_from_name(const std::string& name) {
  if (name == "whitted") return IntegratorKind::Whitted;
  if (name == "direct") return IntegratorKind::DirectLight;
  return std::nullopt;
}

const char* integrator_name(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::Whitted: return "whitted";
    case IntegratorKind::DirectLight: return "direct";
  }
  return "unknown";
}

glm::vec3 Integrator::li(const RenderContext& context, const Ray& ray, Sampler& sampler, ShadingStats& stats) const {
  switch (kind_) {
    case IntegratorKind::Whitted: return whitted_li(context, ray, sampler, stats);
    case IntegratorKind::DirectLight: return direct_light_li(context, ray, sampler, stats);
  }
  return glm::vec3(0.0f);
}

}  // namespace raylab
