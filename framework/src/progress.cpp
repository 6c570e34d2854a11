#include "raylab/progress.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

namespace raylab {

std::string format_duration(double seconds) {
  const auto whole = static_cast<long long>(std::max(0.0, std::floor(seconds)));
  char text[32];
  if (whole < 3600)
    std::snprintf(text, sizeof text, "%lld:%02lld", whole / 60, whole % 60);
  else
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", whole / 3600, whole / 60 % 60, whole % 60);
  return text;
}

double estimate_seconds_left(double fraction, double seconds) {
  if (!(fraction > 0.0)) return -1.0;
  if (fraction >= 1.0) return 0.0;
  return seconds * (1.0 - fraction) / fraction;
}

std::string format_progress(const ProgressState& state) {
  const double fraction = std::clamp(state.fraction, 0.0, 1.0);
  const int percent = fraction >= 1.0 ? 100 : std::min(99, static_cast<int>(fraction * 100.0));
  const double rays_per_second = state.seconds > 0.0 ? static_cast<double>(state.rays) / state.seconds : 0.0;
  const double left = estimate_seconds_left(fraction, state.seconds);
  char text[160];
  std::snprintf(text, sizeof text, "rendering %3d%%  %.1f of %d spp  %.2f Mrays/s  %s elapsed  %s left", percent,
                state.samples_per_pixel, state.samples_per_pixel_goal, rays_per_second * 1e-6,
                format_duration(state.seconds).c_str(), left < 0.0 ? "-:--" : format_duration(std::ceil(left)).c_str());
  return text;
}

ProgressReporter::ProgressReporter(ProgressSettings settings) : settings_(std::move(settings)) {
  start_ = now();
}

double ProgressReporter::now() const {
  if (settings_.clock) return settings_.clock();
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void ProgressReporter::update(ProgressState state) {
  const double time = now();
  state.seconds = time - start_;
  if (state.seconds < settings_.delay) return;  // a quick render says nothing
  if (printed_ && !settings_.terminal && time - last_print_ < settings_.interval) return;
  last_print_ = time;
  print(state);
}

void ProgressReporter::finish(ProgressState state, bool completed) {
  if (!printed_) return;
  state.seconds = now() - start_;
  if (completed) print(state);
  if (settings_.terminal) emit("\n");
}

void ProgressReporter::print(const ProgressState& state) {
  std::string text = format_progress(state);
  if (settings_.terminal) {
    // Back to the line's start; spaces over what is left of a longer line before.
    const std::size_t length = text.size();
    if (length < last_length_) text.append(last_length_ - length, ' ');
    text.insert(0, "\r");
    last_length_ = length;
  } else {
    text += '\n';
  }
  printed_ = true;
  emit(text);
}

void ProgressReporter::emit(const std::string& text) {
  if (settings_.write) {
    settings_.write(text);
  } else {
    std::fputs(text.c_str(), stderr);
    std::fflush(stderr);
  }
}

}  // namespace raylab
