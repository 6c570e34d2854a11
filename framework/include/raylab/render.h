// The renderer: tiles over all cores; each pixel's value depends only on (scene, settings,
// pixel) (with samples_by_noise also on the pilot samples of the pixels around it, all taken
// in a first pass), so any thread count gives bit-identical images.
//
// Per pixel, samples_per_pixel samples: the sampler (sampler.h) gives the point in the pixel
// (its centre at 1 sample, stratified points otherwise), stage 01 turns it into a camera ray,
// the integrator (integrator.h) gives the radiance along it, and a film per tile (film.h; one
// for the whole image with samples_by_noise) keeps the mean and, on request, the variance of
// the mean.
#pragma once

#include "raylab/film.h"
#include "raylab/geometry.h"
#include "raylab/image.h"
#include "raylab/integrator.h"
#include "raylab/progress.h"
#include "raylab/scene.h"
#include "raylab/shading.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace raylab {

struct RenderSettings {
  IntegratorKind integrator = IntegratorKind::Whitted;
  int samples_per_pixel = 1;    // --spp; 1: one ray through each pixel's centre (with
                                // adaptive_tolerance: the most a pixel gets)
  // --adaptive: 0 (off), or stop a pixel's samples once its mean is known to this relative
  // tolerance (PixelConvergence in film.h), asked after every adaptive_batch samples.
  float adaptive_tolerance = 0.0f;
  int adaptive_batch = 32;
  // --spp-by-noise: samples_per_pixel is the average over the image, not every pixel's count.
  // Every pixel first takes kPilotSamples; the rest go where the picture is noisiest
  // (allot_samples_by_noise below). Not together with adaptive_tolerance.
  bool samples_by_noise = false;
  std::uint64_t seed = 0;       // changes every random number (an independent render)
  // Only samples first_sample .. first_sample + sample_count - 1 of each pixel's samples_per_pixel
  // (0: all from first_sample on): a pass of a render made in passes (`raylab view`). Their mean is
  // the picture; the passes' means weighted by their counts give the whole render's. Not with
  // adaptive_tolerance or samples_by_noise.
  int first_sample = 0;
  int sample_count = 0;
  bool track_variance = false;  // also give each pixel's variance of the mean (render_with_variance)
  int max_depth = 5;
  RussianRoulette roulette;  // --roulette: how the path tracer's paths end (default: no roulette)
  int threads = 0;             // 0: one per core this process may use (usable_cores, cores.h)
  // Progress on stderr (progress.h): off unless progress.show (raylab render: unless --quiet).
  ProgressSettings progress;
  // What to leave out (shading.h); the same image either way. Changed only to measure.
  Skips skips;
  TriangleTest triangle_test = TriangleTest::MollerTrumbore;  // --watertight: bonus stage 06_robustness's test
  // Who computes camera rays and primitive tests (geometry.h); by default the stages' own.
  TracingFunctions tracing;
  // Called once by the calling thread as soon as the render's worker threads exist, to start
  // other work beside them: `raylab render` starts loading OpenImageIO for an EXR file
  // (ImageIoPreload, image.h). Work that loads shared libraries must wait until then, as glibc
  // cannot create a thread while another is inside dlopen (it waits for the loader's lock).
  std::function<void()> on_workers_started;
};

struct RenderStats {
  double seconds = 0.0;
  ShadingStats work;  // rays by kind, counted (work.rays() in all)
  int threads = 0;
  // The trees' work over all rays (SceneGeometry::take_thread_work): node boxes tested and
  // primitives tested; 0 where a program's own tree traced them (TracingFunctions::own_tree: it counts nothing).
  std::uint64_t nodes_visited = 0, primitives_tested = 0;
};

// The largest --spp: 2^20 samples per pixel.
constexpr int kMaxSamplesPerPixel = 1 << 20;

struct RenderOutput {
  Image mean;              // each pixel's mean over its samples: the picture
  Image variance_of_mean;  // per pixel and channel, s^2 / n (film.h); 0 x 0 unless track_variance
  Image sample_rate;       // with adaptive_tolerance or samples_by_noise: each pixel's samples /
                           // samples_per_pixel (in all three channels); 0 x 0 otherwise
};

// --spp-by-noise: the samples every pixel takes first, from which the noise is measured.
constexpr int kPilotSamples = 2;
// ... and how far around a pixel it is measured: the (2 r + 1)^2 pixels within r = 3 rows and
// columns of it, less the pixel itself.
constexpr int kNoiseRadius = 3;

// Where --spp-by-noise puts its samples, from `noise`: per pixel (row by row, width x height)
// the variance of its pilot samples as a picture shows them (each channel clamped to [0, 1],
// the channels' variances added). Returns each pixel's count of samples: at least `pilot`,
// average_samples x width x height of them in all (exactly), and the rest shared in proportion
// to each pixel's local standard deviation, the square root of the mean noise of the pixels
// around it (kNoiseRadius), itself left out, and at most 16 times the average (what that limit
// leaves over goes to every pixel alike; so does the rest when nothing is noisy). The share that
// makes the image's summed squared error least is each pixel's standard deviation's. Leaving
// the pixel out keeps its count from following its own samples (a pixel that gets more samples
// because its first ones were far apart would be pulled towards its mean: a bias); they reach
// it only through the image-wide scale of the shares, by about (2 x 3 + 1)^2 parts in the
// number of pixels (docs/09_path.md, section 8).
// Requires average_samples >= pilot >= 1 and noise.size() == width x height (else throws
// std::invalid_argument).
std::vector<std::uint32_t> allot_samples_by_noise(const std::vector<float>& noise, int width, int height,
                                                  int average_samples, int pilot);

// Renders scene.camera's view: each pixel's mean, and its variance of the mean when
// settings.track_variance. Exceptions from stage functions (NotImplemented, ...) stop the
// render and are rethrown here, from the calling thread. Throws std::invalid_argument for
// samples_per_pixel outside [1, kMaxSamplesPerPixel] and for samples outside them.
RenderOutput render_with_variance(const Scene& scene, const RenderSettings& settings, RenderStats* stats = nullptr);

// The geometry render_with_variance traces `scene` through with these settings (their skips,
// triangle test and tracing functions).
SceneGeometry render_geometry(const Scene& scene, const RenderSettings& settings);

// The same on a geometry made by render_geometry(scene, settings) before (`raylab view`'s passes
// build it once); stats->seconds then leaves out its building.
RenderOutput render_with_variance(const Scene& scene, const SceneGeometry& geometry, const RenderSettings& settings,
                                  RenderStats* stats = nullptr);

// The image alone: render_with_variance(...).mean.
Image render(const Scene& scene, const RenderSettings& settings, RenderStats* stats = nullptr);

}  // namespace raylab
