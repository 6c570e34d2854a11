// The progress line of long renders (progress.h): its text, when it is printed (with a fake
// clock: no test here waits or depends on the machine's speed), and a render's counts in it.
#include "raylab/progress.h"
#include "raylab/render.h"
#include "raylab/scene_loader.h"

#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace raylab {
namespace {

using testing::source_path;

TEST(Progress, DurationsReadAsMinutesAndSeconds) {
  EXPECT_EQ(format_duration(0.0), "0:00");
  EXPECT_EQ(format_duration(5.9), "0:05");  // rounded down
  EXPECT_EQ(format_duration(65.0), "1:05");
  EXPECT_EQ(format_duration(600.0), "10:00");
  EXPECT_EQ(format_duration(3723.0), "1:02:03");
  EXPECT_EQ(format_duration(-1.0), "0:00");
}

TEST(Progress, TimeLeftIsWhatIsDoneScaledToTheRest) {
  EXPECT_LT(estimate_seconds_left(0.0, 10.0), 0.0) << "nothing done: unknown";
  EXPECT_DOUBLE_EQ(estimate_seconds_left(0.25, 10.0), 30.0);
  EXPECT_DOUBLE_EQ(estimate_seconds_left(0.5, 60.0), 60.0);
  EXPECT_DOUBLE_EQ(estimate_seconds_left(1.0, 60.0), 0.0);
}

TEST(Progress, LineShowsPercentSamplesRaysElapsedAndLeft) {
  ProgressState state;
  state.fraction = 0.42;
  state.samples_per_pixel = 26.88;
  state.samples_per_pixel_goal = 64;
  state.rays = 94'350'000;  // 1.85 million a second over 51 s
  state.seconds = 51.0;     // 51 x 0.58 / 0.42 = 70.4 s left, rounded up
  EXPECT_EQ(format_progress(state), "rendering  42%  26.9 of 64 spp  1.85 Mrays/s  0:51 elapsed  1:11 left");

  state = ProgressState{};
  EXPECT_EQ(format_progress(state), "rendering   0%  0.0 of 1 spp  0.00 Mrays/s  0:00 elapsed  -:-- left");

  state.fraction = 0.9999;  // not done: the percent is rounded down
  state.seconds = 100.0;
  EXPECT_NE(format_progress(state).find("rendering  99%"), std::string::npos) << format_progress(state);
  state.fraction = 1.0;
  EXPECT_NE(format_progress(state).find("rendering 100%"), std::string::npos) << format_progress(state);
  EXPECT_NE(format_progress(state).find("1:40 elapsed  0:00 left"), std::string::npos) << format_progress(state);
}

// A reporter on a fake clock whose text is kept, with the fake time of each write.
struct FakeTerminal {
  double time = 0.0;
  std::vector<std::string> writes;
  std::vector<double> write_times;

  ProgressSettings settings(bool terminal) {
    ProgressSettings settings;
    settings.show = true;
    settings.terminal = terminal;
    settings.clock = [this] { return time; };
    settings.write = [this](const std::string& text) {
      writes.push_back(text);
      write_times.push_back(time);
    };
    return settings;
  }
  std::string all() const {
    std::string text;
    for (const std::string& write : writes) text += write;
    return text;
  }
};

// A render of `seconds` (fake), updated every quarter of a second as the render does.
void run(ProgressReporter& reporter, FakeTerminal& fake, double seconds, bool completed = true) {
  ProgressState state;
  state.samples_per_pixel_goal = 16;
  for (; fake.time < seconds; fake.time += 0.25) {
    state.fraction = fake.time / seconds;
    state.samples_per_pixel = 16.0 * state.fraction;
    state.rays = static_cast<std::uint64_t>(fake.time * 1e6);
    reporter.update(state);
  }
  fake.time = seconds;
  if (completed) {
    state.fraction = 1.0;
    state.samples_per_pixel = 16.0;
    state.rays = static_cast<std::uint64_t>(seconds * 1e6);
  }
  reporter.finish(state, completed);
}

TEST(Progress, QuickRenderPrintsNothing) {
  for (const bool terminal : {false, true}) {
    FakeTerminal fake;
    ProgressReporter reporter(fake.settings(terminal));
    run(reporter, fake, 1.25);
    EXPECT_TRUE(fake.writes.empty()) << "terminal " << terminal << ": " << fake.all();
    EXPECT_FALSE(reporter.printed());
  }
}

TEST(Progress, NotOnATerminalALineAtLeastEvery5SecondsAndTheFinalState) {
  FakeTerminal fake;
  ProgressReporter reporter(fake.settings(false));
  run(reporter, fake, 60.0);
  ASSERT_GE(fake.writes.size(), 12u) << fake.all();
  // The first line once the render is older than the delay; then never more than 5 s apart.
  EXPECT_GE(fake.write_times.front(), 1.5);
  EXPECT_LE(fake.write_times.front(), 2.0);
  for (std::size_t i = 1; i < fake.write_times.size(); ++i)
    EXPECT_LE(fake.write_times[i] - fake.write_times[i - 1], 5.0) << "between lines " << i - 1 << " and " << i;
  EXPECT_LE(60.0 - fake.write_times.back(), 5.0);
  for (const std::string& line : fake.writes) {
    EXPECT_EQ(line.find('\r'), std::string::npos) << "a carriage return off a terminal: " << line;
    EXPECT_EQ(line.rfind("rendering ", 0), 0u) << line;
    EXPECT_EQ(line.back(), '\n') << line;
  }
  EXPECT_EQ(fake.writes.back(), "rendering 100%  16.0 of 16 spp  1.00 Mrays/s  1:00 elapsed  0:00 left\n");
  EXPECT_NE(fake.writes[1].find("left"), std::string::npos);
  EXPECT_TRUE(reporter.printed());
}

TEST(Progress, OnATerminalOneLineRedrawnInPlaceThenEnded) {
  FakeTerminal fake;
  ProgressReporter reporter(fake.settings(true));
  run(reporter, fake, 10.0);
  // Every update from 1.5 s on (every quarter of a second), then the final state and a line end.
  ASSERT_GE(fake.writes.size(), 30u) << fake.all();
  for (std::size_t i = 0; i + 1 < fake.writes.size(); ++i) {
    EXPECT_EQ(fake.writes[i].rfind("\rrendering ", 0), 0u) << fake.writes[i];
    EXPECT_EQ(fake.writes[i].find('\n'), std::string::npos) << fake.writes[i];
  }
  EXPECT_EQ(fake.writes[fake.writes.size() - 2],
            "\rrendering 100%  16.0 of 16 spp  1.00 Mrays/s  0:10 elapsed  0:00 left");
  EXPECT_EQ(fake.writes.back(), "\n");
}

TEST(Progress, OnATerminalAShorterLineBlanksTheRestOfTheLongerOne) {
  FakeTerminal fake;
  ProgressSettings settings = fake.settings(true);
  settings.delay = 0.0;
  ProgressReporter reporter(settings);
  ProgressState state;
  state.samples_per_pixel_goal = 1000;
  state.samples_per_pixel = 999.0;
  reporter.update(state);
  state.samples_per_pixel_goal = 1;
  state.samples_per_pixel = 0.0;
  reporter.update(state);
  ASSERT_EQ(fake.writes.size(), 2u);
  EXPECT_EQ(fake.writes[0].size(), fake.writes[1].size()) << "[" << fake.writes[0] << "] then [" << fake.writes[1] << "]";
  EXPECT_EQ(fake.writes[1].back(), ' ');
}

TEST(Progress, AFailedRenderEndsTheLineWithoutAFinalState) {
  FakeTerminal on_terminal;
  ProgressReporter terminal_reporter(on_terminal.settings(true));
  run(terminal_reporter, on_terminal, 5.0, false);
  ASSERT_FALSE(on_terminal.writes.empty());
  EXPECT_EQ(on_terminal.writes.back(), "\n");
  EXPECT_EQ(on_terminal.all().find("100%"), std::string::npos) << on_terminal.all();

  FakeTerminal elsewhere;
  ProgressReporter reporter(elsewhere.settings(false));
  run(reporter, elsewhere, 5.0, false);
  ASSERT_FALSE(elsewhere.writes.empty());
  EXPECT_EQ(elsewhere.all().find("100%"), std::string::npos) << elsewhere.all();
}

// A render's own counts: its progress with no delay and no interval, so that every update
// prints, on a clock a millisecond (fake) later at every reading; the final line says what the
// render did. The image is the same as without.
struct RenderProgress {
  double time = 0.0;
  std::vector<std::string> lines;
};

RenderOutput render_with_progress(const Scene& scene, RenderSettings settings, RenderProgress& progress) {
  settings.progress.show = true;
  settings.progress.delay = 0.0;
  settings.progress.interval = 0.0;
  settings.progress.clock = [&progress] { return progress.time += 0.001; };
  settings.progress.write = [&progress](const std::string& text) { progress.lines.push_back(text); };
  return render_with_variance(scene, settings);
}

TEST(Progress, RenderCountsEverySampleAndLeavesTheImageAlone) {
  Scene scene = load_scene(source_path("scenes/cornell.json"));
  scene.camera.width = 40;
  scene.camera.height = 24;
  RenderSettings settings;
  settings.integrator = IntegratorKind::Path;
  settings.max_depth = scene.max_depth;
  settings.samples_per_pixel = 4;
  settings.threads = 2;
  const RenderOutput quiet = render_with_variance(scene, settings);
  RenderProgress progress;
  const RenderOutput shown = render_with_progress(scene, settings, progress);
  EXPECT_EQ(shown.mean.pixels(), quiet.mean.pixels()) << "the progress line changed the image";
  ASSERT_FALSE(progress.lines.empty());
  EXPECT_EQ(progress.lines.back().rfind("rendering 100%  4.0 of 4 spp  ", 0), 0u) << progress.lines.back();
  for (const std::string& line : progress.lines) EXPECT_EQ(line.back(), '\n') << "off a terminal: whole lines";

  // The rays: as many as the render's statistics count, over the (fake) seconds from the
  // reporter's start (the clock's first reading, 0.001) to its last.
  RenderStats stats;
  (void)render_with_variance(scene, settings, &stats);
  char rays[64];
  std::snprintf(rays, sizeof rays, "  %.2f Mrays/s",
                static_cast<double>(stats.work.rays()) / (progress.time - 0.001) * 1e-6);
  EXPECT_NE(progress.lines.back().find(rays), std::string::npos) << progress.lines.back() << " (expected" << rays << ")";
}

TEST(Progress, AdaptiveAndByNoiseRendersEndAt100PercentWithTheirSamples) {
  Scene scene = load_scene(source_path("scenes/cornell.json"));
  scene.camera.width = 32;
  scene.camera.height = 32;
  RenderSettings settings;
  settings.integrator = IntegratorKind::Path;
  settings.max_depth = scene.max_depth;
  settings.threads = 2;

  settings.samples_per_pixel = 64;
  settings.adaptive_tolerance = 0.2f;
  settings.adaptive_batch = 8;
  RenderProgress adaptive;
  const RenderOutput adaptive_output = render_with_progress(scene, settings, adaptive);
  double rate_sum = 0.0;
  for (const glm::vec3& rate : adaptive_output.sample_rate.pixels()) rate_sum += rate.x;
  char samples[64];
  std::snprintf(samples, sizeof samples, "rendering 100%%  %.1f of 64 spp  ",
                rate_sum / static_cast<double>(adaptive_output.sample_rate.pixels().size()) * 64.0);
  ASSERT_FALSE(adaptive.lines.empty());
  EXPECT_EQ(adaptive.lines.back().rfind(samples, 0), 0u) << adaptive.lines.back() << " (expected " << samples << ")";
  EXPECT_EQ(adaptive.lines.back().find(" 64.0 of 64 spp"), std::string::npos) << "every pixel converged early here";

  settings.adaptive_tolerance = 0.0f;
  settings.samples_per_pixel = 6;
  settings.samples_by_noise = true;
  RenderProgress by_noise;
  (void)render_with_progress(scene, settings, by_noise);
  ASSERT_FALSE(by_noise.lines.empty());
  EXPECT_EQ(by_noise.lines.back().rfind("rendering 100%  6.0 of 6 spp  ", 0), 0u) << by_noise.lines.back();
}

}  // namespace
}  // namespace raylab
