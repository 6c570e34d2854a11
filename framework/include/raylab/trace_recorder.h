// What `raylab trace` sees of a Monte Carlo sample (raylab/trace.h): the framework calls that the
// stage code makes while one pixel sample is traced, each with its inputs and its result, in the
// order they were made. The integrators' stage functions (estimate_direct_light, path_radiance)
// are opaque; their calls into the framework are not, and from them the trace rebuilds the path
// the student's code took and what the contract gives along it.
//
// Recording is off (active_trace_recorder is nullptr) but inside a RecordingCalls scope, on the
// thread that made it; a render never records. The hooks: SceneGeometry::intersect and occluded,
// bsdf_sample_f, LightSet::choose and sample_li.
#pragma once

#include "raylab/bsdf.h"
#include "raylab/geometry.h"
#include "raylab/lights.h"
#include "raylab/ray.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace raylab {

struct RecordedCall {
  enum class Kind { Intersect, Occluded, BsdfSample, LightChoice, LightSample };
  Kind kind = Kind::Intersect;
  Ray ray;                                  // Intersect, Occluded
  std::optional<SurfaceHit> hit;            // Intersect
  bool blocked = false;                     // Occluded
  Bsdf bsdf;                                // BsdfSample
  glm::vec3 normal{0.0f}, wo{0.0f};         // BsdfSample
  float u_lobe = 0.0f;                      // BsdfSample; LightChoice: its u
  glm::vec2 u{0.0f};                        // BsdfSample, LightSample
  std::optional<BsdfSample> bsdf_sample;    // BsdfSample
  std::size_t light_index = 0;              // LightChoice
  float choice_probability = 0.0f;          // LightChoice
  Light light;                              // LightSample
  glm::vec3 reference_point{0.0f};          // LightSample
  std::optional<LightSample> light_sample;  // LightSample
};

struct TraceRecorder {
  // At most this many calls are kept (a path that never ends would otherwise fill memory).
  static constexpr std::size_t kMostCalls = 100000;
  std::vector<RecordedCall> calls;
  bool overflowed = false;
  void add(RecordedCall call) {
    if (calls.size() < kMostCalls)
      calls.push_back(std::move(call));
    else
      overflowed = true;
  }
};

// The recorder of this thread's traced sample, or nullptr (always, but under RecordingCalls).
// Defined here, constant-initialised: a hook reads it directly (an extern thread_local defined
// elsewhere is read through a call that checks for its initialisation).
inline thread_local TraceRecorder* active_trace_recorder = nullptr;

// While it lives, this thread records nothing; `recorder` is the recorder it
// paused. A hooked function starts
//   if (RAYLAB_UNLIKELY(active_trace_recorder)) return intersect_recorded(ray);
// and its recorded version, out of line, pauses the recording, calls the
// function again (which then does its work as if no trace ran) and records the
// result with one of the functions below, each of which returns the result it
// records. Not recording, a hook costs one test.
struct PausedRecording {
  TraceRecorder* recorder = active_trace_recorder;
  PausedRecording() { active_trace_recorder = nullptr; }
  ~PausedRecording() { active_trace_recorder = recorder; }
  PausedRecording(const PausedRecording&) = delete;
  PausedRecording& operator=(const PausedRecording&) = delete;
};

std::optional<SurfaceHit> record_intersect(TraceRecorder& recorder, const Ray& ray, std::optional<SurfaceHit> hit);
bool record_occluded(TraceRecorder& recorder, const Ray& ray, bool blocked);
std::optional<BsdfSample> record_bsdf_sample(TraceRecorder& recorder, const Bsdf& bsdf, const glm::vec3& normal,
                                             const glm::vec3& wo, float u_lobe, glm::vec2 u,
                                             std::optional<BsdfSample> sample);
std::size_t record_light_choice(TraceRecorder& recorder, float u, std::size_t index, float probability);
std::optional<LightSample> record_light_sample(TraceRecorder& recorder, const Light& light,
                                               const glm::vec3& reference_point, glm::vec2 u,
                                               std::optional<LightSample> sample);

#if defined(__GNUC__)
#define RAYLAB_UNLIKELY(condition) __builtin_expect(static_cast<bool>(condition), 0)
#define RAYLAB_RECORDED_VERSION __attribute__((noinline, cold))
#else
#define RAYLAB_UNLIKELY(condition) (condition)
#define RAYLAB_RECORDED_VERSION
#endif

// Records this thread's framework calls into `recorder` while it lives.
class RecordingCalls {
 public:
  explicit RecordingCalls(TraceRecorder& recorder) : previous_(active_trace_recorder) {
    active_trace_recorder = &recorder;
  }
  ~RecordingCalls() { active_trace_recorder = previous_; }
  RecordingCalls(const RecordingCalls&) = delete;
  RecordingCalls& operator=(const RecordingCalls&) = delete;

 private:
  TraceRecorder* previous_;
};

}  // namespace raylab
