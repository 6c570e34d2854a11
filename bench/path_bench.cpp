// raylab-bench-path: the path tracer's error against time on the Cornell box, per strategy.
//
//   raylab-bench-path [--width N] [--max-spp N] [--reference-spp N] [--repetitions N] [--output DIR]
//
// Every strategy estimates the same image: scenes/cornell.json at N x N, paths of at most 32
// bounces with Russian roulette (go on with p = 0.8 from the first bounce, as GAMES101's
// assignment 7 does), each pixel the mean over the pixel's area. The reference is the reference
// path tracer (stage 09's path_radiance, --integrator path) at --reference-spp on every core;
// each strategy then renders at 1, 2, 4, ... --max-spp samples per pixel on ONE thread, timed.
// Its mean squared error against the truth is estimated without the reference's own noise:
//   MSE = mean over pixels and channels of (render - reference)^2  -  mean(reference variance of the mean)
// (E[(x - r)^2] = E[(x - truth)^2] + Var(r) when x and r are independent), RMSE = sqrt(MSE), over the
// pixels a picture shows unclipped: those whose reference is at most 1 in every channel (all but the
// light, 40 times brighter than white, and the pixels on its edge, whose error is the light's
// coverage, saturated white in any picture).
// Times are the process's CPU seconds (std::clock) of each one-thread render: on a shared machine
// they do not count the time other processes hold the core, but such a machine still moves them by
// 5-10% from run to run. So every render is made --repetitions times (3 by default), the
// strategies taking turns: each render's time (the CSV, the curves) is the median of its
// repetitions, a strategy's paths per second the median of its repetitions' rates, and the ratio
// against the peer comes with its lowest and highest over the repetitions. Every repetition of a
// render must have the first one's error to the last bit (the same seeds make the same image):
// the bench fails if not.
//
// The strategies (the light is sampled by area, one sample per diffuse vertex, with its shadow ray):
//   bsdf-uniform       no light sampling: directions uniform over the hemisphere, emission
//                      counted wherever a path hits it
//   bsdf-cosine        no light sampling, cosine-weighted directions
//   games101           light sampling + uniform hemisphere directions: GAMES101 assignment 7's
//                      estimator (its castRay), with independent random numbers
//   light-cosine       light sampling + cosine-weighted directions, independent random numbers
//   light-cosine-sobol the same with the kit's stratified samples (raylab/sampler.h: Owen-scrambled
//                      Sobol' points): the reference
//   mis                light sampling and cosine-weighted directions, both counting emission, weighted
//                      by the power heuristic (Veach), stratified samples
//   raylab-reference   not a replica: the renderer itself, render() as raylab-reference render
//                      --integrator path runs it (stage 09's path_radiance, the reference's
//                      geometry), on one thread, with another seed than the reference image's
//                      (at 1 spp it shoots through each pixel's centre, as the renderer does)
//   raylab-reference-auto  the same with --roulette auto: roulette by the path's throughput from
//                      the third surface on (RenderContext::continue_probability) instead of 0.8
//                      from the first; not an estimator of the peer's
//   raylab-reference-by-noise  the same with --spp-by-noise: the samples per pixel are the average,
//                      2 in every pixel and the rest where its neighbours' were noisiest (render.h,
//                      allot_samples_by_noise); fewer samples for an error, each costing more:
//                      even with auto at the peer's error, a few percent sooner below it
// The replica's row: GAMES101 assignment 7 as a student completed it took 784x784 at 16 spp, one
// thread, 31.8 s on this machine on another day (1,436 s as shipped, a new random_device and mt19937
// per number). The times below are set against that fixed figure, which is no ratio to the peer
// (issue 41: a ratio is measured with both programs run alternately, at the peer's own image's
// error): its error is taken as the games101 strategy's at 16 spp (with jittered pixel positions: the peer shoots every
// sample through the pixel centre, which adds aliasing; leaving that out favours the peer), and the
// time each strategy needs to reach that error at 784x784 is (784^2 x samples needed) / (its paths per
// second on one thread), the samples needed read off its own curve (log-log interpolation). So is
// the time to reach RMSE 0.2, 0.1, 0.05 and 0.025, the peer's beside (GAMES101's estimator at the
// peer's paths per second).
// Written to DIR/path_error.csv; plot it with tools/plot_path_error.py.
#include "raylab/bsdf.h"
#include "raylab/geometry.h"
#include "raylab/image.h"
#include "raylab/integrator.h"
#include "raylab/lights.h"
#include "raylab/render.h"
#include "raylab/sampler.h"
#include "raylab/sampling.h"
#include "raylab/scene_loader.h"
#include "raylab/shading.h"
#include "raylab/stages/01_camera_rays.h"
#include "raylab/stages/07_sampling.h"
#include "raylab/stages/09b_mis.h"

#include "../solutions/05c_wide_bvh/fast_tree.h"  // the reference's fastest tree, as raylab-reference traces it

#include <CLI/CLI.hpp>

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace raylab;

constexpr int kMaxDepth = 32;
constexpr float kRoulette = 0.8f;
constexpr double kPeerSeconds = 31.8;  // GAMES101 assignment 7, 784x784, 16 spp, one thread
constexpr int kPeerWidth = 784, kPeerSamples = 16;

enum class Strategy {
  BsdfUniform, BsdfCosine, Games101, LightCosine, LightCosineSobol, Mis, Renderer, RendererAuto, RendererByNoise
};

struct StrategyInfo {
  Strategy strategy;
  const char* name;
  bool light_sampling, uniform_directions, stratified, mis;
};
constexpr StrategyInfo kStrategies[] = {
    {Strategy::BsdfUniform, "bsdf-uniform", false, true, false, false},
    {Strategy::BsdfCosine, "bsdf-cosine", false, false, false, false},
    {Strategy::Games101, "games101", true, true, false, false},
    {Strategy::LightCosine, "light-cosine", true, false, false, false},
    {Strategy::LightCosineSobol, "light-cosine-sobol", true, false, true, false},
    {Strategy::Mis, "mis", true, false, true, true},
    {Strategy::Renderer, "raylab-reference", true, false, true, false},
    {Strategy::RendererAuto, "raylab-reference-auto", true, false, true, false},
    {Strategy::RendererByNoise, "raylab-reference-by-noise", true, false, true, false},
};

// The mis strategy weighs with stage 09b's power_heuristic (the reference's, linked here) and the
// light strategy's density LightSet::pdf_li.
// One sample of the light at a diffuse vertex, with its shadow ray; with MIS, weighted against
// the BSDF sampling of the same direction.
glm::vec3 sample_one_light(const RenderContext& context, const SurfaceHit& hit, const Bsdf& bsdf, const glm::vec3& wo,
                           Sampler& sampler, bool mis) {
  const LightSet& lights = context.lights;
  const float u_choice = sampler.get_1d();
  const glm::vec2 u = sampler.get_2d();
  if (lights.empty()) return glm::vec3(0.0f);
  float choice_probability = 0.0f;
  const Light& light = lights[lights.choose(u_choice, &choice_probability)];
  const std::optional<LightSample> sample = sample_li(light, hit.point, u);
  if (!sample) return glm::vec3(0.0f);
  const glm::vec3 f = bsdf_f(bsdf, hit.geometric_normal, wo, sample->direction);
  if (f == glm::vec3(0.0f)) return glm::vec3(0.0f);
  Ray shadow;
  shadow.origin = offset_ray_origin(hit, sample->direction);
  shadow.direction = sample->point - shadow.origin;
  shadow.t_max = 1.0f - 1e-4f;
  if (context.geometry.occluded(shadow)) return glm::vec3(0.0f);
  const float pdf = sample->pdf * choice_probability;
  const float weight =
      mis && !sample->is_delta ? power_heuristic(1, pdf, 1, bsdf_pdf(bsdf, hit.geometric_normal, wo, sample->direction))
                               : 1.0f;
  return f * sample->radiance * (weight * std::fabs(glm::dot(hit.geometric_normal, sample->direction)) / pdf);
}

// The direction to go on in: the BSDF's own sample, or for a diffuse surface under a uniform
// strategy, a direction uniform over the hemisphere on wo's side.
std::optional<BsdfSample> sample_direction(const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo,
                                           Sampler& sampler, bool uniform) {
  const float u_lobe = sampler.get_1d();
  const glm::vec2 u = sampler.get_2d();
  if (!uniform || bsdf.is_specular()) return bsdf_sample_f(bsdf, normal, wo, u_lobe, u);
  const glm::vec3 facing = glm::dot(normal, wo) >= 0.0f ? normal : -normal;
  BsdfSample sample;
  sample.wi = glm::normalize(Frame(facing).to_world(sample_uniform_hemisphere(u)));
  sample.pdf = uniform_hemisphere_pdf(glm::vec3(0.0f, 0.0f, 1.0f));
  sample.f = bsdf_f(bsdf, normal, wo, sample.wi);
  if (sample.f == glm::vec3(0.0f)) return std::nullopt;
  return sample;
}

glm::vec3 strategy_li(const RenderContext& context, const StrategyInfo& strategy, Ray ray, Sampler& sampler) {
  const Scene& scene = context.scene;
  glm::vec3 radiance(0.0f), throughput(1.0f);
  bool count_emission = true;  // seen from the camera, after a specular bounce, or without light sampling
  float previous_bsdf_pdf = 0.0f;  // MIS: the density of the direction that reached this vertex
  glm::vec3 previous_point(0.0f);
  for (int depth = 0;; ++depth) {
    const std::optional<SurfaceHit> hit = context.geometry.intersect(ray);
    if (!hit) return radiance + throughput * scene.background;
    const Material& material = scene.materials[hit->material];
    const glm::vec3 wo = -glm::normalize(ray.direction);
    const glm::vec3 emitted = emitted_radiance(material, *hit, ray.direction);
    if (count_emission) {
      radiance += throughput * emitted;
    } else if (strategy.mis && emitted != glm::vec3(0.0f)) {
      const float pdf_light = context.lights.pdf_li(previous_point, -wo);
      radiance += throughput * emitted * power_heuristic(1, previous_bsdf_pdf, 1, pdf_light);
    }
    const Bsdf bsdf = bsdf_of(material, diffuse_color_at(material, *hit));
    if (strategy.light_sampling && !bsdf.is_specular())
      radiance += throughput * sample_one_light(context, *hit, bsdf, wo, sampler, strategy.mis);
    if (depth >= kMaxDepth) return radiance;
    if (sampler.get_1d() >= kRoulette) return radiance;
    throughput /= kRoulette;
    const std::optional<BsdfSample> sample =
        sample_direction(bsdf, hit->geometric_normal, wo, sampler, strategy.uniform_directions);
    if (!sample) return radiance;
    throughput *= sample->f * (std::fabs(glm::dot(hit->geometric_normal, sample->wi)) / sample->pdf);
    if (throughput == glm::vec3(0.0f)) return radiance;
    count_emission = !strategy.light_sampling || sample->is_specular;
    previous_bsdf_pdf = sample->pdf;
    previous_point = hit->point;
    ray = spawn_ray(*hit, sample->wi);
  }
}

struct Timed {
  Image image;
  double seconds = 0.0;
};

// One thread: every pixel, samples_per_pixel paths. Independent strategies draw each sample from
// a sampler of its own seed; stratified ones from one sampler of the pixel's samples.
Timed render_strategy(const Scene& scene, const RenderContext& context, const StrategyInfo& strategy,
                      int samples_per_pixel, const RenderSettings& renderer) {
  const Camera& camera = scene.camera;
  Timed result{Image(camera.width, camera.height), 0.0};
  const std::clock_t start = std::clock();
  if (strategy.strategy == Strategy::Renderer || strategy.strategy == Strategy::RendererAuto ||
      strategy.strategy == Strategy::RendererByNoise) {
    RenderSettings settings = renderer;
    settings.samples_per_pixel = samples_per_pixel;
    if (strategy.strategy != Strategy::Renderer) settings.roulette = RussianRoulette{1.0f, true};
    settings.samples_by_noise = strategy.strategy == Strategy::RendererByNoise;
    result.image = render(scene, settings);
    result.seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    return result;
  }
  Sampler stratified(samples_per_pixel, 2);
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      glm::vec3 sum(0.0f);
      for (int s = 0; s < samples_per_pixel; ++s) {
        Sampler independent(1, 1000 + static_cast<std::uint64_t>(s));
        Sampler& sampler = strategy.stratified ? stratified : independent;
        sampler.start_pixel_sample(x, y, strategy.stratified ? s : 0);
        // A jittered point in the pixel (get_2d, not get_pixel_2d: at 1 spp that is the centre).
        const Ray ray = generate_camera_ray(camera, x, y, sampler.get_2d());
        sum += strategy_li(context, strategy, ray, sampler);
      }
      result.image.at(x, y) = sum / static_cast<float>(samples_per_pixel);
    }
  result.seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  return result;
}

bool shown_unclipped(const glm::vec3& reference) { return reference.x <= 1.0f && reference.y <= 1.0f && reference.z <= 1.0f; }

double mean_squared_error(const Image& image, const RenderOutput& reference) {
  double squared = 0.0, reference_variance = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < image.pixels().size(); ++i)
    for (int c = 0; c < 3 && shown_unclipped(reference.mean.pixels()[i]); ++c, ++n) {
      const double difference = static_cast<double>(image.pixels()[i][c]) - reference.mean.pixels()[i][c];
      squared += difference * difference;
      reference_variance += reference.variance_of_mean.pixels()[i][c];
    }
  return n ? (squared - reference_variance) / static_cast<double>(n) : 0.0;
}

struct Point {
  int samples;
  double seconds, rmse;
};

// Samples per pixel at which the curve reaches `rmse` (log-log interpolation, extrapolated with
// the last segment's slope past its ends); 0 if the curve never goes down.
double samples_to_reach(const std::vector<Point>& curve, double rmse) {
  for (std::size_t i = 1; i < curve.size(); ++i) {
    const Point& a = curve[i - 1];
    const Point& b = curve[i];
    if (b.rmse <= rmse || i + 1 == curve.size()) {
      if (!(a.rmse > 0 && b.rmse > 0 && a.rmse != b.rmse)) return 0.0;
      const double slope = std::log(b.samples / static_cast<double>(a.samples)) / std::log(b.rmse / a.rmse);
      return a.samples * std::exp(slope * std::log(rmse / a.rmse));
    }
  }
  return 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"raylab-bench-path: the path tracer's error against time on the Cornell box, per strategy"};
  int width = 128, max_spp = 64, reference_spp = 1024, repetitions = 3;
  std::string output = "bench-results";
  app.add_option("--width", width, "Image width and height")->check(CLI::Range(8, 1024))->capture_default_str();
  app.add_option("--max-spp", max_spp, "Largest samples per pixel of a strategy (1, 2, 4, ... up to it)")
      ->check(CLI::Range(1, 4096))->capture_default_str();
  app.add_option("--reference-spp", reference_spp, "Samples per pixel of the reference (every core)")
      ->check(CLI::Range(16, 1 << 20))->capture_default_str();
  app.add_option("--repetitions", repetitions, "Times each render is made (its time: the median)")
      ->check(CLI::Range(1, 99))->capture_default_str();
  app.add_option("--output", output, "Folder for path_error.csv")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    Scene scene = load_scene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/cornell.json");
    scene.camera.width = scene.camera.height = width;

    RenderSettings settings;
    settings.integrator = IntegratorKind::Path;
    settings.tracing.own_tree = &reference::build_fast_tree;  // as raylab-reference
    settings.samples_per_pixel = reference_spp;
    settings.max_depth = kMaxDepth;
    settings.roulette = RussianRoulette{kRoulette, false};
    settings.seed = 1;
    settings.track_variance = true;
    RenderStats reference_stats;
    std::printf("reference: %dx%d, %d spp, every core ...\n", width, width, reference_spp);
    std::fflush(stdout);
    const RenderOutput reference = render_with_variance(scene, settings, &reference_stats);
    double reference_variance = 0.0;
    std::size_t shown = 0;
    for (std::size_t i = 0; i < reference.mean.pixels().size(); ++i) {
      if (!shown_unclipped(reference.mean.pixels()[i])) continue;
      const glm::vec3& v = reference.variance_of_mean.pixels()[i];
      reference_variance += v.x + v.y + v.z;
      ++shown;
    }
    reference_variance /= 3.0 * static_cast<double>(std::max<std::size_t>(shown, 1));
    std::printf("reference: %.1f s on %d threads; %zu of %zu pixels shown unclipped (the error is theirs); the\n"
                "reference's own RMSE there, about %.5f, is subtracted below\n\n",
                reference_stats.seconds, reference_stats.threads, shown, reference.mean.pixels().size(),
                std::sqrt(reference_variance));

    TracingFunctions reference_tracing;
    reference_tracing.own_tree = &reference::build_fast_tree;  // as raylab-reference
    const SceneGeometry geometry(scene, Acceleration::Bvh, TriangleTest::MollerTrumbore, reference_tracing);
    const RenderContext context(scene, geometry, kMaxDepth, Skips{}, RussianRoulette{kRoulette, false});
    std::filesystem::create_directories(output);
    std::ofstream csv(output + "/path_error.csv");
    csv << "strategy,spp,seconds,paths_per_second,rmse\n";
    const double pixels = static_cast<double>(width) * width;
    RenderSettings renderer = settings;  // the raylab-reference row: one thread, another seed
    renderer.threads = 1;
    renderer.seed = 2;
    renderer.track_variance = false;
    // seconds[strategy][k][repetition] for 2^k spp; the images' errors, the same at every repetition.
    constexpr std::size_t kStrategyCount = std::size(kStrategies);
    std::vector<std::vector<std::vector<double>>> seconds(kStrategyCount);
    std::vector<std::vector<double>> errors(kStrategyCount);
    for (int repetition = 0; repetition < repetitions; ++repetition) {
      std::printf("repetition %d of %d ...\n", repetition + 1, repetitions);
      std::fflush(stdout);
      for (std::size_t i = 0; i < kStrategyCount; ++i) {
        std::size_t k = 0;
        for (int spp = 1; spp <= max_spp; spp *= 2, ++k) {
          const Timed timed = render_strategy(scene, context, kStrategies[i], spp, renderer);
          const double rmse = std::sqrt(std::max(0.0, mean_squared_error(timed.image, reference)));
          if (repetition == 0) {
            errors[i].push_back(rmse);
            seconds[i].emplace_back();
          } else if (rmse != errors[i][k]) {
            throw std::runtime_error(std::string(kStrategies[i].name) + " at " + std::to_string(spp) +
                                     " spp: another image at repetition " + std::to_string(repetition + 1) +
                                     " (RMSE " + std::to_string(rmse) + ", first " + std::to_string(errors[i][k]) +
                                     "): a render must not depend on its run");
          }
          // (A render too short for the clock counts as one tick, so that no rate is infinite.)
          seconds[i][k].push_back(std::max(timed.seconds, 1.0 / CLOCKS_PER_SEC));
        }
      }
    }
    const auto median = [](std::vector<double> values) {
      std::sort(values.begin(), values.end());
      const std::size_t n = values.size();
      return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    };
    std::printf("\n%-25s %5s %11s %12s %9s   (CPU seconds: the median of %d)\n", "strategy", "spp", "CPU seconds",
                "paths/s", "RMSE", repetitions);
    std::vector<std::vector<Point>> curves(kStrategyCount);
    // Paths per second over a repetition's renders of the strategy, each repetition's, and their median.
    std::vector<std::vector<double>> paths_per_second_each(kStrategyCount);
    std::vector<double> paths_per_second(kStrategyCount);
    for (std::size_t i = 0; i < kStrategyCount; ++i) {
      double paths = 0.0;
      std::vector<double> seconds_each(static_cast<std::size_t>(repetitions), 0.0);
      for (std::size_t k = 0; k < errors[i].size(); ++k) {
        const int spp = 1 << k;
        const double time = median(seconds[i][k]);
        curves[i].push_back({spp, time, errors[i][k]});
        paths += pixels * spp;
        for (std::size_t r = 0; r < seconds_each.size(); ++r) seconds_each[r] += seconds[i][k][r];
        std::printf("%-25s %5d %11.3f %12.0f %9.5f\n", kStrategies[i].name, spp, time, pixels * spp / time,
                    errors[i][k]);
        csv << kStrategies[i].name << ',' << spp << ',' << time << ',' << pixels * spp / time << ',' << errors[i][k]
            << '\n';
      }
      for (const double each : seconds_each) paths_per_second_each[i].push_back(paths / each);
      paths_per_second[i] = median(paths_per_second_each[i]);
    }

    // The peer's error: the games101 strategy at 16 spp (read off its curve).
    const std::vector<Point>& games101 = curves[static_cast<int>(Strategy::Games101)];
    double peer_rmse = 0.0;
    for (const Point& point : games101)
      if (point.samples == kPeerSamples) peer_rmse = point.rmse;
    const double peer_pixels = static_cast<double>(kPeerWidth) * kPeerWidth;
    const double peer_paths_per_second = peer_pixels * kPeerSamples / kPeerSeconds;
    if (peer_rmse > 0.0) {
      std::printf("\nThe replica's error: GAMES101's estimator (the games101 row, a replica of the peer's) at %d spp,\n"
                  "RMSE %.5f at %dx%d.\n",
                  kPeerSamples, peer_rmse, width, width);
      std::printf("Time to reach it at %dx%d on one thread, and a fixed %.1f s (the peer's, measured on another day)\n"
                  "over it. Not a ratio to the peer: its error is the replica's, not the peer's own image's, and the\n"
                  "peer did not run beside it (docs/performance.md gives the ratio measured side by side):\n",
                  kPeerWidth, kPeerWidth, kPeerSeconds);
      std::printf("%-25s %12s %14s %10s %14s %17s\n", "strategy", "paths/s", "spp needed", "seconds", "31.8 s / this",
                  "lowest - highest");
      for (std::size_t i = 0; i < curves.size(); ++i) {
        const double spp = samples_to_reach(curves[i], peer_rmse);
        // peer / this at a rate of paths per second: the peer's seconds over this strategy's
        const auto against_peer = [&](double rate) {
          return spp > 0 ? kPeerSeconds / (peer_pixels * spp / rate) : 0.0;
        };
        const auto [lowest, highest] =
            std::minmax_element(paths_per_second_each[i].begin(), paths_per_second_each[i].end());
        std::printf("%-25s %12.0f %14.2f %10.2f %13.1fx %8.1fx - %4.1fx\n", kStrategies[i].name, paths_per_second[i],
                    spp, peer_pixels * spp / paths_per_second[i], against_peer(paths_per_second[i]),
                    against_peer(*lowest), against_peer(*highest));
      }
      std::printf("(31.8 s: %.0f paths/s on one thread; paths/s: the median of the repetitions')\n",
                  peer_paths_per_second);
    } else {
      std::printf("\n(--max-spp below %d: no comparison with the peer's %d-spp render)\n", kPeerSamples, kPeerSamples);
    }

    // The time to each error level: seconds at 784x784 on one thread, from each curve's samples
    // needed (read between its measured points only: "-" outside them) and its paths per second.
    // The peer's row: GAMES101's estimator's samples at the peer's measured rate.
    const double levels[] = {0.2, 0.1, 0.05, 0.025};
    const auto within = [](const std::vector<Point>& curve, double rmse) {
      return curve.size() > 1 && rmse <= curve.front().rmse && rmse >= curve.back().rmse;
    };
    std::printf("\nSeconds to each RMSE (as measured at %dx%d) at %dx%d on one thread:\n%-25s", width, width,
                kPeerWidth, kPeerWidth, "strategy");
    for (const double level : levels) std::printf(" %9.3f", level);
    std::printf("\n%-25s", "replica at 31.8 s' rate");
    for (const double level : levels) {
      if (within(games101, level))
        std::printf(" %9.2f", peer_pixels * samples_to_reach(games101, level) / peer_paths_per_second);
      else
        std::printf(" %9s", "-");
    }
    for (std::size_t i = 0; i < curves.size(); ++i) {
      std::printf("\n%-25s", kStrategies[i].name);
      for (const double level : levels) {
        if (within(curves[i], level))
          std::printf(" %9.2f", peer_pixels * samples_to_reach(curves[i], level) / paths_per_second[i]);
        else
          std::printf(" %9s", "-");
      }
    }
    std::printf("\n\nCSV written to %s/path_error.csv\n", output.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raylab-bench-path: %s\n", e.what());
    return 1;
  }
  return 0;
}
