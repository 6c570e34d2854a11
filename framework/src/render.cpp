#include "raylab/render.h"

#include "raylab/geometry.h"
#include "raylab/stages/01_camera_rays.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace raylab {
namespace {

constexpr int kTileSize = 16;

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

void print_progress(std::size_t done, std::size_t total, double seconds, std::uint64_t rays) {
  const double fraction = total ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
  const double eta = fraction > 0 ? seconds * (1.0 - fraction) / fraction : 0.0;
  const double mrays = seconds > 0 ? static_cast<double>(rays) / seconds * 1e-6 : 0.0;
  constexpr int kBarWidth = 30;
  char bar[kBarWidth + 1];
  const int filled = static_cast<int>(fraction * kBarWidth);
  for (int i = 0; i < kBarWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kBarWidth] = '\0';
  std::fprintf(stderr, "\r[%s] %3.0f%%  ETA %5.1f s  %7.2f Mrays/s ", bar, fraction * 100.0, eta, mrays);
  std::fflush(stderr);
}

}  // namespace

RenderOutput render_with_variance(const Scene& scene, const RenderSettings& settings, RenderStats* stats) {
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
  const Camera& camera = scene.camera;
  RenderOutput output;
  output.mean = Image(camera.width, camera.height);
  if (settings.track_variance) output.variance_of_mean = Image(camera.width, camera.height);
  if (adaptive) output.sample_rate = Image(camera.width, camera.height);
  const SceneGeometry geometry(scene, settings.skips.no_bvh_for_small_sets ? Acceleration::Bvh : Acceleration::BvhAlways,
                               settings.triangle_test, settings.tracing);
  const auto camera_ray = settings.tracing.camera_ray ? settings.tracing.camera_ray : generate_camera_ray;
  const RenderContext context(scene, geometry, settings.max_depth, settings.skips, settings.roulette);
  const Integrator integrator(settings.integrator);
  const int samples_per_pixel = settings.samples_per_pixel;
  const bool one_plain_sample = samples_per_pixel == 1 && !settings.track_variance && !adaptive;
  const std::vector<Tile> tiles = make_tiles(camera.width, camera.height);

  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const int thread_count = std::max(1, std::min<int>(settings.threads > 0 ? settings.threads : static_cast<int>(hardware),
                                                      static_cast<int>(tiles.size())));
  std::atomic<std::size_t> next_tile{0}, tiles_done{0};
  std::atomic<std::uint64_t> rays{0};  // for the progress line, read while workers run
  std::atomic<bool> stop{false};
  ShadingStats total_work;
  std::mutex work_mutex;
  std::exception_ptr first_error;
  std::mutex error_mutex;

  // Each worker takes tiles from the shared counter and writes only its tiles' pixels.
  auto worker = [&] {
    try {
      for (std::size_t t = next_tile++; t < tiles.size() && !stop; t = next_tile++) {
        const Tile& tile = tiles[t];
        ShadingStats tile_stats;
        Sampler sampler(samples_per_pixel, settings.seed);
        std::optional<Film> film;
        if (!one_plain_sample) film.emplace(tile.x1 - tile.x0, tile.y1 - tile.y0, settings.track_variance);
        for (int y = tile.y0; y < tile.y1; ++y)
          for (int x = tile.x0; x < tile.x1; ++x) {
            if (one_plain_sample) {  // the mean of one sample is that sample: no film needed
              sampler.start_pixel_sample(x, y, 0);
              const Ray ray = camera_ray(camera, x, y, sampler.get_pixel_2d());
              output.mean.at(x, y) = integrator.li(context, ray, sampler, tile_stats);
              continue;
            }
            PixelConvergence convergence;  // adaptive sampling: a pixel's samples depend on it alone
            for (int sample = 0; sample < samples_per_pixel; ++sample) {
              sampler.start_pixel_sample(x, y, sample);
              const Ray ray = camera_ray(camera, x, y, sampler.get_pixel_2d());
              const glm::vec3 value = integrator.li(context, ray, sampler, tile_stats);
              film->add_sample(x - tile.x0, y - tile.y0, value);
              if (!adaptive) continue;
              convergence.add(value);
              if ((sample + 1) % settings.adaptive_batch == 0 && convergence.converged(settings.adaptive_tolerance))
                break;
            }
            if (adaptive)
              output.sample_rate.at(x, y) = glm::vec3(static_cast<float>(
                  static_cast<double>(convergence.count()) / static_cast<double>(samples_per_pixel)));
            output.mean.at(x, y) = film->mean_at(x - tile.x0, y - tile.y0);
            if (settings.track_variance)
              output.variance_of_mean.at(x, y) = film->variance_of_mean_at(x - tile.x0, y - tile.y0);
          }
        rays += tile_stats.rays();
        {
          std::lock_guard<std::mutex> lock(work_mutex);
          total_work += tile_stats;
        }
        ++tiles_done;
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!first_error) first_error = std::current_exception();
      stop = true;
    }
  };

  std::vector<std::thread> threads;
  try {
    for (int i = 0; i < thread_count; ++i) threads.emplace_back(worker);
    if (settings.on_workers_started) settings.on_workers_started();
  } catch (...) {  // no thread to be had (std::system_error): stop the ones started, then say why
    stop = true;
    for (std::thread& thread : threads) thread.join();
    throw;
  }
  if (settings.show_progress) {
    while (tiles_done < tiles.size() && !stop) {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      print_progress(tiles_done, tiles.size(), seconds, rays);
    }
  }
  for (std::thread& thread : threads) thread.join();
  if (settings.show_progress) std::fprintf(stderr, "\r%*s\r", 78, "");
  if (first_error) std::rethrow_exception(first_error);

  if (stats) {
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->work = total_work;
    stats->threads = thread_count;
  }
  return output;
}

Image render(const Scene& scene, const RenderSettings& settings, RenderStats* stats) {
  return render_with_variance(scene, settings, stats).mean;
}

}  // namespace raylab
