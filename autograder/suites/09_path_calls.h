// Stage 09's batch call (09_path_calls.cpp): a picture rendered with path_radiance (or, for the
// bonus stage 09b, with path_radiance_mis).
#pragma once

#include "raylab/image.h"
#include "raylab/trace.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace raylab::grading {

// A scene file of the kit rendered with the path integrator (path_radiance, or path_radiance_mis
// when `mis` is 1), with changes for the test: each pixel's mean and its variance of the mean
// (film.h).
struct PathRenderRequest {
  int width = 32, height = 32, samples_per_pixel = 4, max_depth = 5;
  float roulette_probability = 1.0f;
  float albedo = -1.0f;  // >= 0: every material's diffuse colour becomes this grey (furnaces)
  std::uint64_t seed = 0;
  // 1: no picture, one path_radiance call along the camera's view direction (the stage's probe:
  // it reaches path_radiance before any other stage's function), returned as a 1x1 picture.
  int probe_only = 0;
  int probe_away = 0;  // with probe_only: along the opposite direction, away from look_at
  int mis = 0;  // 1: stage 09b's path_radiance_mis instead of path_radiance
  glm::vec3 background{-1.0f};  // every channel >= 0: the scene's background becomes this
};
struct PathRenderResult {
  Image mean, variance_of_mean;
};
PathRenderResult path_render(const std::string& scene_path, const PathRenderRequest& request);

// Pixel (x, y) of that picture (not a probe's) traced as the report shows a failing picture's
// pixel (raylab/trace.h): its samples in turn, from sample 0, until one's trace disagrees with the
// contract; that one, or sample 0's when none of the first kMostTracedPathSamples does (as many as
// the graded pictures have: a sample that makes the pixel differ is among them).
// settings.sample says which; `chinese`: the steps' words in Chinese.
constexpr int kMostTracedPathSamples = 128;
PixelTrace path_trace_pixel(const std::string& scene_path, const PathRenderRequest& request, int x, int y,
                            bool chinese);

}  // namespace raylab::grading
