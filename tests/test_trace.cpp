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
  int paths = 0, surfaces_after_the_first = 0, mis_weights = 0;
  for (const char* name : {"cornell", "cornell_specular", "furnace", "whitted", "mis_plates"}) {
    const Scene scene = scene_named(name);
    for (const IntegratorKind integrator : {IntegratorKind::DirectLight, IntegratorKind::Path, IntegratorKind::PathMis})
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
            for (const TraceStep& step : trace.steps) {
              if (step.call.rfind("surface 1:", 0) == 0) ++surfaces_after_the_first;
              mis_weights += step.function == "power_heuristic";
            }
          }
  }
  EXPECT_EQ(paths, 5 * 3 * 3 * 4 * 4);
  // The paths go on past their first surface (the trace follows bounces, not only camera hits),
  // and MIS's weights are traced.
  EXPECT_GT(surfaces_after_the_first, 100);
  EXPECT_GT(mis_weights, 100);
}

// Through the trees (the bunny's, the Cornell box's over its objects): on every pixel that hits,
// the nodes from the root down to the leaf of the closest hit, each box entered, the leaves opened
// all entered before the hit, the primitive tested; and the camera ray drawn to the hit.
TEST(Trace, TheReferenceAgreesThroughTheTrees) {
  const TracingFunctions contract = testkit::exact_tracing();
  for (const char* name : {"bunny", "cornell"}) {
    Scene scene = scene_named(name);
    scene.camera.width = 64;
    scene.camera.height = 48;
    int box_steps = 0, hits = 0;
    for (int y = 1; y < 48; y += 4)
      for (int x = 1; x < 64; x += 4) {
        const PixelTrace trace = trace_pixel(scene, x, y, TraceSettings{}, contract);
        EXPECT_EQ(trace.first_disagreement(), -1) << name << " (" << x << ", " << y << ")";
        ASSERT_GE(trace.segments.size(), 1u);
        EXPECT_EQ(trace.segments[0].kind, TraceSegment::Kind::Camera);
        int boxes = 0, tested = 0, leaves = 0;
        for (const TraceStep& step : trace.steps) {
          boxes += step.function == "intersect_ray_box";
          if (step.function != "intersect_bvh") continue;
          if (step.call.find("the leaves your intersect_bvh opened") == 0) {
            ++leaves;
            EXPECT_EQ(step.yours.find(" 0 the ray misses, 0 entered beyond"), step.yours.find(';') + 1) << step.yours;
          } else {
            ++tested;
            EXPECT_EQ(step.yours.rfind("tested ", 0), 0u) << step.yours;
          }
        }
        // A hit on a primitive under a tree: its path (at least the root), then the traversal's
        // leaves and whether it tested the primitive.
        EXPECT_EQ(tested, boxes > 0 ? 1 : 0) << name << " (" << x << ", " << y << ")";
        EXPECT_EQ(leaves, tested) << name << " (" << x << ", " << y << ")";
        box_steps += boxes;
        hits += tested;
      }
    EXPECT_GT(hits, 20) << name << ": few pixels hit a primitive under a tree";
    EXPECT_GE(box_steps, 2 * hits) << name << ": fewer than two boxes on the way to a hit";
  }
}

// Whitted's rays after the camera ray (the Whitted scene's mirror-like glass sphere, its floor
// under two point lights): each agrees, each is drawn, and a pixel seen through the glass follows
// its reflection and refraction rays down to the shadow rays of the floor behind it.
TEST(Trace, TheReferenceAgreesAlongWhittedsRays) {
  const TracingFunctions contract = testkit::exact_tracing();
  Scene scene = scene_named("whitted");
  scene.camera.width = 128;
  scene.camera.height = 96;
  int reflections = 0, refractions = 0, shadow_rays = 0;
  for (int y = 2; y < 96; y += 6)
    for (int x = 2; x < 128; x += 6) {
      const PixelTrace trace = trace_pixel(scene, x, y, TraceSettings{}, contract);
      EXPECT_EQ(trace.first_disagreement(), -1) << "(" << x << ", " << y << ")";
      int rays = 0;
      for (const TraceStep& step : trace.steps) {
        const bool reflection = step.call.find(": the reflection ray") != std::string::npos;
        const bool refraction = step.call.find(": the refraction ray") != std::string::npos;
        const bool shadow = step.call.find(": the shadow ray towards light") != std::string::npos;
        reflections += reflection;
        refractions += refraction;
        shadow_rays += shadow;
        rays += reflection || refraction || shadow;
      }
      EXPECT_LE(rays, 24) << "(" << x << ", " << y << ")";
      // Each ray drawn: the camera ray, then one segment per ray after it.
      ASSERT_EQ(trace.segments.size(), static_cast<std::size_t>(rays) + 1) << "(" << x << ", " << y << ")";
    }
  EXPECT_GT(reflections, 10);
  EXPECT_GT(refractions, 10);
  EXPECT_GT(shadow_rays, 40);
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
