// The progress of a long render, on stderr (`raylab render`; --quiet turns it off).
//
// The render's worker threads count what they finish (samples, pixels, rays) in atomic
// counters (render.cpp); the thread that called render reads them a few times a second and
// gives them to a ProgressReporter, which decides what to print: nothing while the render is
// younger than `delay` (so quick renders stay quiet); then, on a terminal, one line redrawn in
// place (a carriage return before it), and anywhere else a new line every `interval` seconds;
// and the final state when the render ends. A line reads, e.g.
//
//   rendering  42%  26.9 of 64 spp  1.85 Mrays/s  0:51 elapsed  1:11 left
//
// Nothing here changes the image: the counters are only read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace raylab {

// What a progress line shows.
struct ProgressState {
  double fraction = 0.0;           // of the render done, in [0, 1]
  double samples_per_pixel = 0.0;  // samples taken so far / pixels in the image
  int samples_per_pixel_goal = 1;  // --spp (with --adaptive the most, with --spp-by-noise the average)
  std::uint64_t rays = 0;          // rays traced so far: camera, reflection, refraction and shadow rays
  double seconds = 0.0;            // since the render started tracing
};

// "0:05", "1:05" (a minute and 5 seconds), "1:02:03" from an hour on; seconds rounded down.
std::string format_duration(double seconds);

// The seconds left if the rest goes as fast as what is done so far:
// seconds x (1 - fraction) / fraction. Negative (unknown) while nothing is done.
double estimate_seconds_left(double fraction, double seconds);

// One progress line, without a line end (the example above). The percent is rounded down and
// the time left up, so 100% and 0:00 left mean done; the time left reads "-:--" while unknown.
std::string format_progress(const ProgressState& state);

struct ProgressSettings {
  bool show = false;      // raylab render: unless --quiet
  bool terminal = false;  // stderr is a terminal: one line, redrawn in place
  double delay = 1.5;     // seconds: nothing is printed for a render that ends sooner
  double interval = 3.0;  // seconds between lines when not on a terminal (on one: every update)
  // Seconds from any fixed start; empty: std::chrono::steady_clock. Tests pass a fake clock.
  std::function<double()> clock;
  // Where the text goes; empty: stderr.
  std::function<void(const std::string&)> write;
};

class ProgressReporter {
 public:
  // The clock's time now is the start.
  explicit ProgressReporter(ProgressSettings settings);

  // The render's state now (the reporter fills in state.seconds from its clock); prints a line
  // if it is time for one. Called by one thread, as often as it likes.
  void update(ProgressState state);

  // The render ended. If a line was printed: when `completed`, the final state; on a terminal
  // the line is ended, so what follows starts a line of its own.
  void finish(ProgressState state, bool completed);

  // Whether anything was printed.
  bool printed() const { return printed_; }

 private:
  double now() const;
  void print(const ProgressState& state);
  void emit(const std::string& text);  // to settings_.write, else stderr

  ProgressSettings settings_;
  double start_ = 0.0;
  double last_print_ = 0.0;
  bool printed_ = false;
  std::size_t last_length_ = 0;  // on a terminal: the line on screen, to blank what a shorter one leaves
};

}  // namespace raylab
