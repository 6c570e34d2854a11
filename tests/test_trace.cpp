// raylab trace (raylab/trace.h) with the reference stages: along every path it follows, each of the
// reference's calls agrees with the contract, whatever the scene, integrator, roulette or sample;
// and recording never outlives the trace.
#include "raylab/scene_loader.h"
#include "raylab/testkit/exact_tracing.h"
#include "raylab/trace.h"
#include "raylab/trace_recorder.h"

#include <gtest/gtest.h>

#include <string>

namespace raylab {
namespace {

Scene scene_named(const std::string& name) {
  return load_scene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/" + name + ".json");
}

TEST(Trace, TheReferenceAgreesAlongEveryPath) {
  const TracingFunctions contract = testkit::exact_tracing();
  int paths = 0, surfaces_after_the_first = 0;
  for (const char* name : {"cornell", "cornell_specular", "furnace", "whitted", "mis_plates"}) {
    const Scene scene = scene_named(name);
    for (const IntegratorKind integrator : {IntegratorKind::DirectLight, IntegratorKind::Path})
      for (const char* roulette : {"1", "0.6", "auto"})
        for (int pixel = 0; pixel < 4; ++pixel)
          for (int sample = 0; sample < 4; ++sample) {
            TraceSettings settings;
            settings.integrator = integrator;
            settings.samples_per_pixel = 4;
            settings.sample = sample;
            settings.max_depth = scene.max_depth;
            settings.roulette = *RussianRoulette::from_text(roulette);
            const int x = (scene.camera.width * (2 * pixel + 1)) / 8, y = (scene.camera.height * (pixel + 2)) / 7;
            const PixelTrace trace = trace_pixel(scene, x, y, settings, contract);
            const int first = trace.first_disagreement();
            EXPECT_EQ(first, -1) << name << ", " << integrator_name(integrator) << ", roulette " << roulette
                                 << ", pixel (" << x << ", " << y << "), sample " << sample << ": step " << first + 1
                                 << " (" << (first >= 0 ? trace.steps[first].call : "") << ") disagrees";
            ++paths;
            for (const TraceStep& step : trace.steps)
              if (step.call.rfind("surface 1:", 0) == 0) ++surfaces_after_the_first;
          }
  }
  EXPECT_EQ(paths, 5 * 2 * 3 * 4 * 4);
  // The paths go on past their first surface (the trace follows bounces, not only camera hits).
  EXPECT_GT(surfaces_after_the_first, 100);
}

TEST(Trace, RecordsOnlyWhileItTraces) {
  const Scene scene = scene_named("cornell");
  TraceSettings settings;
  settings.integrator = IntegratorKind::Path;
  EXPECT_EQ(active_trace_recorder, nullptr);
  (void)trace_pixel(scene, 100, 100, settings, testkit::exact_tracing());
  EXPECT_EQ(active_trace_recorder, nullptr);
  TraceRecorder recorder;
  {
    RecordingCalls recording(recorder);
    EXPECT_EQ(active_trace_recorder, &recorder);
    {
      PausedRecording paused;
      EXPECT_EQ(active_trace_recorder, nullptr);
      EXPECT_EQ(paused.recorder, &recorder);
    }
    EXPECT_EQ(active_trace_recorder, &recorder);
  }
  EXPECT_EQ(active_trace_recorder, nullptr);
}

TEST(Trace, ASampleOutsideThePixelIsBadInput) {
  const Scene scene = scene_named("cornell");
  TraceSettings settings;
  settings.samples_per_pixel = 4;
  settings.sample = 4;
  EXPECT_THROW((void)trace_pixel(scene, 0, 0, settings, testkit::exact_tracing()), std::invalid_argument);
}

}  // namespace
}  // namespace raylab
