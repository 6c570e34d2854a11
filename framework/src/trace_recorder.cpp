#include "raylab/trace_recorder.h"

#include <utility>

namespace raylab {

std::optional<SurfaceHit> record_intersect(TraceRecorder& recorder, const Ray& ray, std::optional<SurfaceHit> hit) {
  RecordedCall call;
  call.kind = RecordedCall::Kind::Intersect;
  call.ray = ray;
  call.hit = hit;
  recorder.add(std::move(call));
  return hit;
}

bool record_occluded(TraceRecorder& recorder, const Ray& ray, bool blocked) {
  RecordedCall call;
  call.kind = RecordedCall::Kind::Occluded;
  call.ray = ray;
  call.blocked = blocked;
  recorder.add(std::move(call));
  return blocked;
}

std::optional<BsdfSample> record_bsdf_sample(TraceRecorder& recorder, const Bsdf& bsdf, const glm::vec3& normal,
                                             const glm::vec3& wo, float u_lobe, glm::vec2 u,
                                             std::optional<BsdfSample> sample) {
  RecordedCall call;
  call.kind = RecordedCall::Kind::BsdfSample;
  call.bsdf = bsdf;
  call.normal = normal;
  call.wo = wo;
  call.u_lobe = u_lobe;
  call.u = u;
  call.bsdf_sample = sample;
  recorder.add(std::move(call));
  return sample;
}

std::size_t record_light_choice(TraceRecorder& recorder, float u, std::size_t index, float probability) {
  RecordedCall call;
  call.kind = RecordedCall::Kind::LightChoice;
  call.u_lobe = u;
  call.light_index = index;
  call.choice_probability = probability;
  recorder.add(std::move(call));
  return index;
}

std::optional<LightSample> record_light_sample(TraceRecorder& recorder, const Light& light,
                                               const glm::vec3& reference_point, glm::vec2 u,
                                               std::optional<LightSample> sample) {
  RecordedCall call;
  call.kind = RecordedCall::Kind::LightSample;
  call.light = light;
  call.reference_point = reference_point;
  call.u = u;
  call.light_sample = sample;
  recorder.add(std::move(call));
  return sample;
}

}  // namespace raylab
