#include "raylab/render.h"

#include "raylab/cores.h"
#include "raylab/geometry.h"
#include "raylab/progress.h"
#include "raylab/stages/01_camera_rays.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace raylab {
namespace {

constexpr int kTileSize = 16;
// How often the calling thread reads the progress counters (and a terminal's line is redrawn).
constexpr std::chrono::milliseconds kProgressTick(250);

struct Tile {
  int x0, y0, x1, y1;
};

std::vector<Tile> make_tiles(int width, int height) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += kTileSize)
    for (int x = 0; x < width; x += kTileSize)
      tiles.push_back({x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)});
  return tiles;
}

// What the progress line counts (progress.h): one worker's, added to by it after each row of a
// tile and read by the thread that shows the progress. On a cache line of its own, so that no
// worker waits for another's: three additions per row, nothing next to the row's samples.
struct alignas(64) ProgressCounters {
  std::atomic<std::uint64_t> samples{0};  // samples taken
  std::atomic<std::uint64_t> pixels{0};   // pixels finished (in the last pass)
  std::atomic<std::uint64_t> rays{0};     // rays traced
};

// One tile's part: after each of its rows, adds what the row did to its worker's counters.
class TileProgress {
 public:
  TileProgress(ProgressCounters& counters, const ShadingStats& tile_stats) : counters_(counters), tile_stats_(tile_stats) {}
  // A row of the tile is done: `pixels` finished, `samples` taken.
  void row_done(int pixels, std::uint64_t samples) {
    const std::uint64_t rays = tile_stats_.rays();
    counters_.samples.fetch_add(samples, std::memory_order_relaxed);
    counters_.pixels.fetch_add(static_cast<std::uint64_t>(pixels), std::memory_order_relaxed);
    counters_.rays.fetch_add(rays - rays_told_, std::memory_order_relaxed);
    rays_told_ = rays;
  }

 private:
  ProgressCounters& counters_;
  const ShadingStats& tile_stats_;
  std::uint64_t rays_told_ = 0;
};

}  // namespace

std::vector<std::uint32_t> allot_samples_by_noise(const std::vector<float>& noise, int width, int height,
                                                  int average_samples, int pilot) {
  if (width < 1 || height < 1 || noise.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw std::invalid_argument("allot_samples_by_noise: " + std::to_string(noise.size()) + " noise values for a " +
                                std::to_string(width) + "x" + std::to_string(height) + " image");
  if (pilot < 1 || average_samples < pilot)
    throw std::invalid_argument("allot_samples_by_noise: an average of " + std::to_string(average_samples) +
                                " samples with " + std::to_string(pilot) + " first: needs average >= first >= 1");
  const std::size_t count = noise.size();
  const auto w = static_cast<std::size_t>(width);
  // A summed-area table of the noise (a value that is not finite and positive counts as 0).
  std::vector<double> table((w + 1) * (static_cast<std::size_t>(height) + 1), 0.0);
  const auto noise_at = [&](std::size_t i) {
    const double value = noise[i];
    return value > 0.0 && value < kInfinity ? value : 0.0;
  };
  for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y)
    for (std::size_t x = 0; x < w; ++x)
      table[(y + 1) * (w + 1) + x + 1] =
          noise_at(y * w + x) + table[y * (w + 1) + x + 1] + table[(y + 1) * (w + 1) + x] - table[y * (w + 1) + x];
  // Each pixel's local standard deviation: the pixels around it, itself left out.
  std::vector<double> deviation(count, 0.0);
  double deviation_sum = 0.0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const auto x0 = static_cast<std::size_t>(std::max(0, x - kNoiseRadius));
      const auto x1 = static_cast<std::size_t>(std::min(width, x + kNoiseRadius + 1));
      const auto y0 = static_cast<std::size_t>(std::max(0, y - kNoiseRadius));
      const auto y1 = static_cast<std::size_t>(std::min(height, y + kNoiseRadius + 1));
      const std::size_t i = static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x);
      const double around = table[y1 * (w + 1) + x1] - table[y0 * (w + 1) + x1] - table[y1 * (w + 1) + x0] +
                            table[y0 * (w + 1) + x0] - noise_at(i);
      const std::size_t others = (x1 - x0) * (y1 - y0) - 1;
      deviation[i] = others > 0 ? std::sqrt(std::max(0.0, around) / static_cast<double>(others)) : 0.0;
      deviation_sum += deviation[i];
    }
  // What each pixel wants beyond the pilot: its share of the average by its deviation, at most
  // 16 times the average (a few wild samples around a pixel do not take the image's budget).
  const double average = static_cast<double>(average_samples);
  std::vector<double> wanted(count, 0.0);
  double wanted_sum = 0.0;
  if (deviation_sum > 0.0) {
    const double mean_deviation = deviation_sum / static_cast<double>(count);
    for (std::size_t i = 0; i < count; ++i) {
      const double share = std::min(average * deviation[i] / mean_deviation, 16.0 * average);
      wanted[i] = std::max(0.0, share - pilot);
      wanted_sum += wanted[i];
    }
  }
  // The rest of the budget: what is wanted, scaled down to fit (the shares add up to the
  // average, so without the limit more is wanted than there is), or, where the limit left some
  // over (or nothing is noisy), that much more for every pixel. Rounded so the total is exact:
  // each pixel gets the whole samples its running total crosses.
  const auto rest = static_cast<std::uint64_t>(average_samples - pilot) * count;
  const double scale = wanted_sum > static_cast<double>(rest) ? static_cast<double>(rest) / wanted_sum : 1.0;
  const double left_over = std::max(0.0, static_cast<double>(rest) - wanted_sum) / static_cast<double>(count);
  std::vector<std::uint32_t> samples(count, static_cast<std::uint32_t>(pilot));
  double running = 0.0;
  std::uint64_t given = 0;
  for (std::size_t i = 0; i < count; ++i) {
    running += wanted[i] * scale + left_over;
    const std::uint64_t upto = i + 1 == count ? rest : std::min(rest, static_cast<std::uint64_t>(running));
    if (upto > given) {
      samples[i] += static_cast<std::uint32_t>(upto - given);
      given = upto;
    }
  }
  return samples;
}

SceneGeometry render_geometry(const Scene& scene, const RenderSettings& settings) {
  return SceneGeometry(scene, settings.skips.no_bvh_for_small_sets ? Acceleration::Bvh : Acceleration::BvhAlways,
                       settings.triangle_test, settings.tracing);
}

RenderOutput render_with_variance(const Scene& scene, const RenderSettings& settings, RenderStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const SceneGeometry geometry = render_geometry(scene, settings);
  RenderOutput output = render_with_variance(scene, geometry, settings, stats);
  if (stats) stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return output;
}

RenderOutput render_with_variance(const Scene& scene, const SceneGeometry& geometry, const RenderSettings& settings,
                                  RenderStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  if (settings.samples_per_pixel < 1 || settings.samples_per_pixel > kMaxSamplesPerPixel)
    throw std::invalid_argument("samples per pixel must be in [1, " + std::to_string(kMaxSamplesPerPixel) +
                                "], got " + std::to_string(settings.samples_per_pixel));
  const bool adaptive = settings.adaptive_tolerance != 0.0f;
  if (adaptive && !(settings.adaptive_tolerance > 0.0f && settings.adaptive_tolerance <= 1.0f))
    throw std::invalid_argument("adaptive sampling: the tolerance must be in (0, 1], got " +
                                std::to_string(settings.adaptive_tolerance));
  if (adaptive && settings.adaptive_batch < 2)
    throw std::invalid_argument("adaptive sampling: a batch must be at least 2 samples, got " +
                                std::to_string(settings.adaptive_batch));
  if (adaptive && settings.samples_by_noise)
    throw std::invalid_argument("adaptive sampling and samples by noise: choose one");
  const int first_sample = settings.first_sample;
  if (first_sample < 0 || first_sample >= settings.samples_per_pixel || settings.sample_count < 0 ||
      settings.sample_count > settings.samples_per_pixel - first_sample)
    throw std::invalid_argument("samples " + std::to_string(first_sample) + " and " +
                                std::to_string(settings.sample_count) + " more: not within the pixel's " +
                                std::to_string(settings.samples_per_pixel));
  const int end_sample = settings.sample_count > 0 ? first_sample + settings.sample_count : settings.samples_per_pixel;
  if ((first_sample > 0 || end_sample < settings.samples_per_pixel) && (adaptive || settings.samples_by_noise))
    throw std::invalid_argument("a render in passes: not with adaptive sampling or samples by noise");
  const Camera& camera = scene.camera;
  RenderOutput output;
  output.mean = Image(camera.width, camera.height);
  if (settings.track_variance) output.variance_of_mean = Image(camera.width, camera.height);
  if (adaptive || settings.samples_by_noise) output.sample_rate = Image(camera.width, camera.height, glm::vec3(1.0f));
  const auto camera_ray = settings.tracing.camera_ray ? settings.tracing.camera_ray : generate_camera_ray;
  const RenderContext context(scene, geometry, settings.max_depth, settings.skips, settings.roulette);
  const Integrator integrator(settings.integrator);
  const int samples_per_pixel = settings.samples_per_pixel;
  // Samples by noise: two passes over the image, the pilot samples and then the rest (with at
  // most kPilotSamples on average there is no rest to share: every pixel takes them all).
  const bool by_noise = settings.samples_by_noise && samples_per_pixel > kPilotSamples;
  const bool one_plain_sample = samples_per_pixel == 1 && !settings.track_variance && !adaptive;
  const int samples_taken = end_sample - first_sample;  // per pixel (adaptive: the most; by noise: the average)
  const std::vector<Tile> tiles = make_tiles(camera.width, camera.height);
  // One pixel sample: the sampler started at it, its camera ray, and the radiance along it.
  const auto trace_sample = [&](int x, int y, int sample, Sampler& sampler, ShadingStats& tile_stats) {
    sampler.start_pixel_sample(x, y, sample);
    const Ray ray = camera_ray(camera, x, y, sampler.get_pixel_2d());
    return integrator.li(context, ray, sampler, tile_stats);
  };

  // The passes over the image (by noise: the pilot samples, then the rest), made by the same worker
  // threads: a worker takes a pass's tiles from its shared counter and writes only its tiles'
  // pixels; once every worker has finished a pass, the last one runs between_passes (by noise:
  // the samples' shares) and all go on to the next. (New threads for a pass could wait: the
  // image I/O loads beside the first pass, and glibc makes a new thread wait while a library loads.)
  // A pass renders a tile at a time, and tells `progress` after each of the tile's rows.
  using Pass = std::function<void(const Tile&, ShadingStats&, Sampler&, TileProgress& progress)>;
  std::vector<Pass> passes;
  std::function<void()> between_passes;
  std::vector<std::uint32_t> shares;  // by noise: each pixel's samples in all
  std::optional<Film> image_film;     // by noise: one film for the whole image, kept between the passes
  std::vector<float> noise;           // by noise: each pixel's pilot variance as a picture shows it
  const auto width = static_cast<std::size_t>(camera.width);

  if (!by_noise) {
    // One pass; each tile keeps a film of its own.
    passes.push_back([&](const Tile& tile, ShadingStats& tile_stats, Sampler& sampler, TileProgress& progress) {
                        std::optional<Film> film;
                        if (!one_plain_sample) film.emplace(tile.x1 - tile.x0, tile.y1 - tile.y0, settings.track_variance);
                        for (int y = tile.y0; y < tile.y1; ++y) {
                          std::uint64_t row_samples = 0;
                          for (int x = tile.x0; x < tile.x1; ++x) {
                            if (one_plain_sample) {  // the mean of one sample is that sample: no film needed
                              output.mean.at(x, y) = trace_sample(x, y, 0, sampler, tile_stats);
                              ++row_samples;
                              continue;
                            }
                            PixelConvergence convergence;  // adaptive sampling: a pixel's samples depend on it alone
                            for (int sample = first_sample; sample < end_sample; ++sample) {
                              const glm::vec3 value = trace_sample(x, y, sample, sampler, tile_stats);
                              film->add_sample(x - tile.x0, y - tile.y0, value);
                              if (!adaptive) continue;
                              convergence.add(value);
                              if ((sample + 1) % settings.adaptive_batch == 0 &&
                                  convergence.converged(settings.adaptive_tolerance))
                                break;
                            }
                            row_samples += adaptive ? convergence.count() : static_cast<std::uint32_t>(samples_taken);
                            if (adaptive)
                              output.sample_rate.at(x, y) = glm::vec3(static_cast<float>(
                                  static_cast<double>(convergence.count()) / static_cast<double>(samples_per_pixel)));
                            output.mean.at(x, y) = film->mean_at(x - tile.x0, y - tile.y0);
                            if (settings.track_variance)
                              output.variance_of_mean.at(x, y) = film->variance_of_mean_at(x - tile.x0, y - tile.y0);
                          }
                          progress.row_done(tile.x1 - tile.x0, row_samples);
                        }
                      });
  } else {
    image_film.emplace(camera.width, camera.height, settings.track_variance);
    noise.assign(width * static_cast<std::size_t>(camera.height), 0.0f);
    // Pass 1: every pixel's pilot samples, and their variance as a picture shows them (each channel
    // clamped to [0, 1], NaN as 0; the channels' variances added).
    passes.push_back([&](const Tile& tile, ShadingStats& tile_stats, Sampler& sampler, TileProgress& progress) {
                        for (int y = tile.y0; y < tile.y1; ++y) {
                          for (int x = tile.x0; x < tile.x1; ++x) {
                            glm::dvec3 sum(0.0), sum_of_squares(0.0);
                            for (int sample = 0; sample < kPilotSamples; ++sample) {
                              const glm::vec3 value = trace_sample(x, y, sample, sampler, tile_stats);
                              image_film->add_sample(x, y, value);
                              glm::dvec3 shown;
                              for (int c = 0; c < 3; ++c) shown[c] = value[c] > 0.0f ? std::min(value[c], 1.0f) : 0.0f;
                              sum += shown;
                              sum_of_squares += shown * shown;
                            }
                            const glm::dvec3 variance =
                                (sum_of_squares - sum * sum / static_cast<double>(kPilotSamples)) / (kPilotSamples - 1.0);
                            noise[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)] =
                                static_cast<float>(std::max(0.0, variance.x + variance.y + variance.z));
                          }
                          // No pixel finished yet: the second pass finishes them.
                          progress.row_done(0, static_cast<std::uint64_t>(tile.x1 - tile.x0) * kPilotSamples);
                        }
                      });
    between_passes = [&] {
      shares = allot_samples_by_noise(noise, camera.width, camera.height, samples_per_pixel, kPilotSamples);
    };
    // Pass 2: each pixel's samples from kPilotSamples up to its share.
    passes.push_back([&](const Tile& tile, ShadingStats& tile_stats, Sampler& sampler, TileProgress& progress) {
                        for (int y = tile.y0; y < tile.y1; ++y) {
                          std::uint64_t row_samples = 0;
                          for (int x = tile.x0; x < tile.x1; ++x) {
                            const std::uint32_t share =
                                shares[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)];
                            row_samples += share - kPilotSamples;
                            for (std::uint32_t sample = kPilotSamples; sample < share; ++sample) {
                              image_film->add_sample(x, y, trace_sample(x, y, static_cast<int>(sample), sampler, tile_stats));
                            }
                            output.mean.at(x, y) = image_film->mean_at(x, y);
                            if (settings.track_variance)
                              output.variance_of_mean.at(x, y) = image_film->variance_of_mean_at(x, y);
                            output.sample_rate.at(x, y) = glm::vec3(
                                static_cast<float>(static_cast<double>(share) / static_cast<double>(samples_per_pixel)));
                          }
                          progress.row_done(tile.x1 - tile.x0, row_samples);
                        }
                      });
  }

  // Not told: one thread per core it may use, as many as the address-space limit has room for.
  const unsigned automatic = std::min(usable_cores(), threads_within_address_space_limit());
  const int thread_count = std::max(1, std::min<int>(settings.threads > 0 ? settings.threads : static_cast<int>(std::min(automatic, 4096u)),
                                                      static_cast<int>(tiles.size())));
  std::unique_ptr<std::atomic<std::size_t>[]> next_tile(new std::atomic<std::size_t>[passes.size()]);
  for (std::size_t p = 0; p < passes.size(); ++p) next_tile[p] = 0;
  std::vector<ProgressCounters> progress_counters(static_cast<std::size_t>(thread_count));  // one per worker
  std::atomic<bool> stop{false};
  ShadingStats total_work;
  SceneGeometry::Work total_tree_work;
  std::mutex work_mutex;
  std::exception_ptr first_error;
  std::mutex error_mutex;
  const auto keep_error = [&] {
    std::lock_guard<std::mutex> lock(error_mutex);
    if (!first_error) first_error = std::current_exception();
    stop = true;
  };
  // Between passes: the workers that finished the current one, and the passes done by all.
  std::mutex pass_mutex;
  std::condition_variable pass_finished;
  int workers_finished = 0;
  std::size_t passes_done = 0;
  bool threads_failed = false;  // not every worker could be started: nobody waits for the others
  // The workers still at work, for the calling thread while it shows the progress.
  std::mutex end_mutex;
  std::condition_variable worker_ended;
  int workers_running = thread_count;

  auto worker = [&](int index) {
    for (std::size_t p = 0; p < passes.size(); ++p) {
      try {
        for (std::size_t t = next_tile[p]++; t < tiles.size() && !stop; t = next_tile[p]++) {
          ShadingStats tile_stats;
          Sampler sampler(samples_per_pixel, settings.seed);
          TileProgress tile_progress(progress_counters[static_cast<std::size_t>(index)], tile_stats);
          (void)SceneGeometry::take_thread_work();  // what this thread traced before the tile
          passes[p](tiles[t], tile_stats, sampler, tile_progress);
          const SceneGeometry::Work tile_tree_work = SceneGeometry::take_thread_work();
          std::lock_guard<std::mutex> lock(work_mutex);
          total_work += tile_stats;
          total_tree_work.nodes += tile_tree_work.nodes;
          total_tree_work.primitives += tile_tree_work.primitives;
        }
      } catch (...) {
        keep_error();
      }
      if (p + 1 == passes.size()) break;
      std::unique_lock<std::mutex> lock(pass_mutex);
      if (++workers_finished == thread_count) {
        workers_finished = 0;
        if (!stop) {
          try {
            between_passes();
          } catch (...) {
            keep_error();
          }
        }
        ++passes_done;
        pass_finished.notify_all();
      } else {
        pass_finished.wait(lock, [&] { return passes_done > p || threads_failed; });
      }
    }
    std::lock_guard<std::mutex> lock(end_mutex);
    if (--workers_running == 0) worker_ended.notify_one();
  };

  // The progress line's state from the counters: the fraction done by samples taken, with
  // adaptive sampling (where a pixel's samples are not known before) by pixels finished.
  const double pixel_count = static_cast<double>(camera.width) * static_cast<double>(camera.height);
  const auto progress_state = [&] {
    std::uint64_t samples = 0, pixels = 0, rays = 0;
    for (const ProgressCounters& counters : progress_counters) {
      samples += counters.samples.load(std::memory_order_relaxed);
      pixels += counters.pixels.load(std::memory_order_relaxed);
      rays += counters.rays.load(std::memory_order_relaxed);
    }
    ProgressState state;
    state.fraction = adaptive ? static_cast<double>(pixels) / pixel_count
                              : static_cast<double>(samples) / (pixel_count * samples_taken);
    state.samples_per_pixel = static_cast<double>(samples) / pixel_count;
    state.samples_per_pixel_goal = samples_per_pixel;
    state.rays = rays;
    return state;
  };
  std::optional<ProgressReporter> progress;  // its clock starts here, as the tracing does
  if (settings.progress.show) progress.emplace(settings.progress);

  std::vector<std::thread> threads;
  const auto stop_started_threads = [&] {
    stop = true;
    {
      std::lock_guard<std::mutex> lock(pass_mutex);
      threads_failed = true;
    }
    pass_finished.notify_all();
    for (std::thread& thread : threads) thread.join();
  };
  try {
    for (int i = 0; i < thread_count; ++i) threads.emplace_back(worker, i);
  } catch (const std::system_error& error) {  // no thread to be had: stop the ones started, then say why
    const std::size_t started = threads.size();
    stop_started_threads();
    throw std::runtime_error("could not start render thread " + std::to_string(started + 1) + " of " +
                             std::to_string(thread_count) + " (" + error.what() +
                             "): fewer --threads, or a larger memory or process limit");
  }
  try {
    if (settings.on_workers_started) settings.on_workers_started();
  } catch (...) {
    stop_started_threads();
    throw;
  }
  if (progress) {
    // Reads the counters now and then every kProgressTick until the last worker ends.
    std::unique_lock<std::mutex> lock(end_mutex);
    do {
      lock.unlock();
      progress->update(progress_state());
      lock.lock();
    } while (!worker_ended.wait_for(lock, kProgressTick, [&] { return workers_running == 0; }));
  }
  for (std::thread& thread : threads) thread.join();
  if (progress) progress->finish(progress_state(), !first_error);
  if (first_error) std::rethrow_exception(first_error);

  if (stats) {
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->work = total_work;
    stats->threads = thread_count;
    stats->nodes_visited = total_tree_work.nodes;
    stats->primitives_tested = total_tree_work.primitives;
  }
  return output;
}

Image render(const Scene& scene, const RenderSettings& settings, RenderStats* stats) {
  return render_with_variance(scene, settings, stats).mean;
}

}  // namespace raylab
