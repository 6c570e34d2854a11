#include "raylab/cli.h"

#include "raylab/error.h"
#include "raylab/image.h"
#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/trace.h"
#include "raylab/tree_bench.h"
#include "raylab/view_worker.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>
#if defined(_WIN32)
#include <io.h>
#define RAYLAB_ISATTY(stream) (::_isatty(::_fileno(stream)) != 0)
#define RAYLAB_DUP(fd) ::_dup(fd)
#define RAYLAB_DUP2(from, to) ::_dup2(from, to)
#define RAYLAB_WRITE(fd, bytes, size) ::_write(fd, bytes, static_cast<unsigned>(size))
#else
#include <unistd.h>
#define RAYLAB_ISATTY(stream) (::isatty(::fileno(stream)) != 0)
#define RAYLAB_DUP(fd) ::dup(fd)
#define RAYLAB_DUP2(from, to) ::dup2(from, to)
#define RAYLAB_WRITE(fd, bytes, size) ::write(fd, bytes, size)
#endif

namespace raylab {
namespace {

// RussianRoulette::kLeastProbability as the messages write it.
std::string least_roulette_text() {
  std::ostringstream text;
  text << RussianRoulette::kLeastProbability;
  return text.str();
}

// RAYLAB_PROGRESS_SECONDS=S: the progress shown from S seconds on and a line every S seconds
// off a terminal, instead of 1.5 and 3 (the tests set 0: every render shows it at once).
std::optional<double> progress_seconds_from_environment() {
  const char* text = std::getenv("RAYLAB_PROGRESS_SECONDS");
  if (!text || !*text) return std::nullopt;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  if (*end != '\0' || !(seconds >= 0.0))
    throw UsageError(std::string("RAYLAB_PROGRESS_SECONDS: expected a number of seconds (0 or more), got '") + text + "'");
  return seconds;
}

struct RenderOptions {
  std::string scene_path;
  std::string output_path;
  int width = 0, height = 0;  // 0: the scene's
  int max_depth = -1;         // -1: the scene's
  int threads = 0;            // 0: one per core this process may use
  int samples_per_pixel = 1;
  std::string roulette = "1";  // the path tracer's Russian roulette: a probability, or "auto"
  std::uint64_t seed = 0;
  std::string integrator;     // empty: the scene's ("integrator", whitted by default)
  std::string variance_path;  // empty: no variance image
  float adaptive = 0.0f;      // --adaptive: 0 (off) or the tolerance
  int adaptive_batch = 32;    // --adaptive-batch
  bool samples_by_noise = false;  // --spp-by-noise
  std::string sample_rate_path;  // empty: no sample-rate image
  bool quiet = false;
  bool watertight = false;
  TriangleTreeBuilder own_tree = nullptr;  // run_cli's: the program's own tree, or nullptr
  // --accel: which stage trees (StageTree's words); given, the program's own tree is not used
  // (raylab-reference traces the reference's code of that tree as a student's program traces
  // the student's).
  std::string accel = "best";
  bool accel_given = false;
};

// The tree --accel names (raylab render's and raylab trace's).
StageTree accel_option(const std::string& accel) {
  const std::optional<StageTree> tree = stage_tree_named(accel);
  if (!tree) throw UsageError("--accel: unknown tree '" + accel + "' (known: " + stage_tree_words() + ")");
  return *tree;
}

// What --accel says, in one line (raylab render's first): the tree the geometry traces, and why
// better ones were passed over.
std::string tree_choice_text(const SceneGeometry::TreeChoice& choice) {
  std::string text;
  if (choice.small_sets_only) {
    text = "raylab: tree: none needed, every set of primitives is small (4 or fewer): each is tested";
  } else if (!choice.own_tree.empty()) {
    text = "raylab: tree: " + choice.own_tree;
  } else {
    if (choice.used == StageTree::None) {
      text = choice.stub_stage.empty()
                 ? "raylab: tree: none, every primitive tested (--accel none)"
                 : "raylab: tree: none, every primitive tested: stage " + choice.stub_stage + " is not written yet";
    } else {
      const StageTreeFacts& tree = stage_tree_facts(choice.used);
      text = std::string("raylab: tree: your ") + tree.what + " (stage " + tree.stage + "; --accel " +
             stage_tree_name(choice.used) + ")";
    }
  }
  for (const std::string& why : choice.passed_over) text += "\n  not used: " + why;
  return text;
}

// --integrator and --roulette of raylab render and raylab trace: checked before the scene loads
// (an unknown name is a usage error, whatever the scene), then the integrator that runs (the
// option's, else the scene's).
void check_integrator_option(const std::string& name) {
  if (!name.empty() && !integrator_from_name(name))
    throw UsageError("--integrator: unknown integrator '" + name + "' (known: whitted, direct, path, mis)");
}
IntegratorKind integrator_of(const std::string& option, const Scene& scene) {
  const std::optional<IntegratorKind> integrator = integrator_from_name(option.empty() ? scene.integrator : option);
  if (!integrator) throw UsageError("unknown integrator '" + scene.integrator + "'");
  return *integrator;
}
RussianRoulette roulette_option(const std::string& text) {
  const std::optional<RussianRoulette> roulette = RussianRoulette::from_text(text);
  if (!roulette)
    throw UsageError("--roulette: expected a probability in [" + least_roulette_text() + ", 1] or auto, got '" + text +
                     "'");
  return *roulette;
}

// The scene and the settings of raylab render (and of the view's worker) from their options.
struct RenderSetup {
  Scene scene;
  RenderSettings settings;
};
RenderSetup render_setup(const RenderOptions& options) {
  if (options.adaptive != 0.0f && options.samples_by_noise)
    throw UsageError("--adaptive and --spp-by-noise: choose one (each decides how many samples a pixel gets)");
  check_integrator_option(options.integrator);
  const RussianRoulette roulette = roulette_option(options.roulette);
  Scene scene = load_scene(options.scene_path);
  const IntegratorKind integrator = integrator_of(options.integrator, scene);
  if (options.width > 0) scene.camera.width = options.width;
  if (options.height > 0) scene.camera.height = options.height;
  try {
    validate_camera(scene.camera);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--width/--height: ") + e.what());
  }
  RenderSettings settings;
  settings.integrator = integrator;
  settings.samples_per_pixel = options.samples_per_pixel;
  settings.seed = options.seed;
  settings.track_variance = !options.variance_path.empty();
  settings.adaptive_tolerance = options.adaptive;
  settings.adaptive_batch = options.adaptive_batch;
  settings.samples_by_noise = options.samples_by_noise;
  settings.max_depth = options.max_depth >= 0 ? options.max_depth : scene.max_depth;
  settings.roulette = roulette;
  settings.threads = options.threads;
  if (options.watertight) settings.triangle_test = TriangleTest::Watertight;
  settings.tracing.tree = accel_option(options.accel);
  if (!options.accel_given) settings.tracing.own_tree = options.own_tree;
  return {std::move(scene), settings};
}

int run_render(const RenderOptions& options) {
  check_image_extension(options.output_path);
  if (!options.variance_path.empty()) check_image_extension(options.variance_path);
  if (!options.sample_rate_path.empty()) {
    check_image_extension(options.sample_rate_path);
    if (options.adaptive == 0.0f && !options.samples_by_noise)
      throw UsageError("--sample-rate: only with --adaptive or --spp-by-noise (without them every pixel gets --spp samples)");
  }
  RenderSetup setup = render_setup(options);
  const Scene& scene = setup.scene;
  RenderSettings& settings = setup.settings;
  // Progress on stderr for renders longer than a second or two (progress.h): on a terminal one
  // line redrawn in place, elsewhere (a pipe, a file, an IDE's console) a line every few seconds.
  settings.progress.show = !options.quiet;
  settings.progress.terminal = RAYLAB_ISATTY(stderr);
  if (const std::optional<double> seconds = progress_seconds_from_environment()) {
    settings.progress.delay = *seconds;
    settings.progress.interval = *seconds;
  }
  // OpenImageIO, when an EXR file is to be written, loaded beside the render once its workers
  // run; waited for by the first write (and before this function returns or throws). PNG and
  // PPM files are written without it.
  std::optional<ImageIoPreload> image_io_preload;
  if (writes_through_openimageio(options.output_path) || writes_through_openimageio(options.variance_path) ||
      writes_through_openimageio(options.sample_rate_path))
    settings.on_workers_started = [&image_io_preload] { image_io_preload.emplace(); };
  const auto start = std::chrono::steady_clock::now();
  const SceneGeometry geometry = render_geometry(scene, settings);
  if (!options.quiet) std::fprintf(stderr, "%s\n", tree_choice_text(geometry.tree_choice()).c_str());
  RenderStats stats;
  const RenderOutput output = render_with_variance(scene, geometry, settings, &stats);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Image& image = output.mean;
  write_image(image, options.output_path);
  if (!options.variance_path.empty()) write_image(output.variance_of_mean, options.variance_path);
  if (!options.sample_rate_path.empty()) write_image(output.sample_rate, options.sample_rate_path);
  std::string samples = std::to_string(settings.samples_per_pixel) + " spp";
  if (options.adaptive != 0.0f) {
    double rate_sum = 0.0;
    for (const glm::vec3& rate : output.sample_rate.pixels()) rate_sum += rate.x;
    char text[96];
    std::snprintf(text, sizeof text, "adaptive, %.1f of at most %d spp on average",
                  rate_sum / static_cast<double>(output.sample_rate.pixels().size()) * settings.samples_per_pixel,
                  settings.samples_per_pixel);
    samples = text;
  }
  if (options.samples_by_noise) samples += " on average, by noise";
  // The trees' work per ray, where it was counted (not by a program's own tree).
  std::string work;
  const std::uint64_t rays = stats.work.rays();
  if (rays > 0 && stats.nodes_visited + stats.primitives_tested > 0) {
    char text[96];
    std::snprintf(text, sizeof text, "; %.1f nodes and %.1f primitives per ray",
                  static_cast<double>(stats.nodes_visited) / static_cast<double>(rays),
                  static_cast<double>(stats.primitives_tested) / static_cast<double>(rays));
    work = text;
  }
  if (!options.quiet)
    std::fprintf(stderr, "rendered %s: %dx%d at %s in %.3f s on %d threads (%.2f Mrays/s%s) -> %s\n",
                 options.scene_path.c_str(), image.width(), image.height(), samples.c_str(), stats.seconds,
                 stats.threads, stats.seconds > 0 ? static_cast<double>(rays) / stats.seconds * 1e-6 : 0.0,
                 work.c_str(), options.output_path.c_str());
  return kExitOk;
}

// `raylab trace`: one pixel's calls against the contract's answers.
struct TraceOptions {
  std::string scene_path;
  std::vector<int> pixel;
  int width = 0, height = 0;  // 0: the scene's
  int sample = 0;
  int samples_per_pixel = 1;
  std::uint64_t seed = 0;
  int max_depth = -1;  // -1: the scene's
  std::string roulette = "1";
  std::string integrator;  // empty: the scene's
  std::string language = "en";
  bool json = false;
  std::string accel = "best";  // as raylab render's: the tree whose walk the trace shows
};

int run_trace(const TraceOptions& options, const TracingFunctions& contract) {
  check_integrator_option(options.integrator);
  const RussianRoulette roulette = roulette_option(options.roulette);
  if (options.sample >= options.samples_per_pixel)
    throw UsageError("--sample " + std::to_string(options.sample) + ": the pixel has " +
                     std::to_string(options.samples_per_pixel) + " sample" +
                     (options.samples_per_pixel == 1 ? "" : "s") + " (--spp), numbered from 0");
  Scene scene = load_scene(options.scene_path);
  if (options.width > 0) scene.camera.width = options.width;
  if (options.height > 0) scene.camera.height = options.height;
  TraceSettings settings;
  settings.integrator = integrator_of(options.integrator, scene);
  settings.samples_per_pixel = options.samples_per_pixel;
  settings.sample = options.sample;
  settings.seed = options.seed;
  settings.max_depth = options.max_depth >= 0 ? options.max_depth : scene.max_depth;
  settings.roulette = roulette;
  settings.chinese = options.language == "zh";
  settings.yours.tree = accel_option(options.accel);
  if (!options.json) {
    print_trace(std::cout, options.scene_path, trace_pixel(scene, options.pixel[0], options.pixel[1], settings, contract));
    return kExitOk;
  }
  // --json: what the stage code prints goes to stderr, so that stdout holds the JSON alone.
  std::fflush(stdout);
  std::cout.flush();
  const int json_out = RAYLAB_DUP(1);
  if (json_out < 0 || RAYLAB_DUP2(2, 1) < 0) throw InputError("--json: cannot keep stdout for the JSON");
  const PixelTrace trace = trace_pixel(scene, options.pixel[0], options.pixel[1], settings, contract);
  std::ostringstream json;
  write_trace_json(json, scene.camera, trace);
  std::fflush(stdout);
  std::cout.flush();
  const std::string text = json.str();
  for (std::size_t written = 0; written < text.size();) {
    const auto n = RAYLAB_WRITE(json_out, text.data() + written, text.size() - written);
    if (n <= 0) throw InputError("--json: cannot write the JSON to stdout");
    written += static_cast<std::size_t>(n);
  }
  return kExitOk;
}

// `raylab view-worker` (not listed in --help): the view server's renderer (view_worker.h).
int run_view_worker_command(const RenderOptions& options, int first_sample, int frames_fd, bool send_tree) {
  RenderSetup setup = render_setup(options);
  // The view draws the levels of the trees it traces: the stage trees, not a program's own.
  setup.settings.tracing.own_tree = nullptr;
  setup.settings.first_sample = first_sample;
  if (first_sample >= setup.settings.samples_per_pixel)
    throw UsageError("--first-sample " + std::to_string(first_sample) + ": the render has " +
                     std::to_string(setup.settings.samples_per_pixel) + " samples per pixel (--spp)");
  return run_view_worker(setup.scene, setup.settings, frames_fd, send_tree);
}

// `raylab view ...`: the view's server is a program of its own, raylab-view beside this one (it
// links the HTTP library, which every other command would load for nothing, and no stage code
// runs in it); it is handed this program's path, whose view-worker and trace commands it runs.
int run_view(const char* program, const std::vector<std::string>& arguments) {
#if defined(_WIN32)
  (void)program;
  (void)arguments;
  throw UsageError("view: only on Linux for now (raylab render and raylab trace work here)");
#else
  std::string self = program;
  char resolved[4096];
  const ssize_t length = ::readlink("/proc/self/exe", resolved, sizeof resolved - 1);
  if (length > 0) self.assign(resolved, static_cast<std::size_t>(length));
  const std::string::size_type slash = self.rfind('/');
  const std::string server = (slash == std::string::npos ? std::string() : self.substr(0, slash + 1)) + "raylab-view";
  std::vector<std::string> words{server, "--renderer", self};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  ::execv(server.c_str(), argv.data());
  throw InputError(server + ": cannot start the view's server (" + std::strerror(errno) +
                   "): build it with cmake --build build (the target raylab-view; it needs libcpp-httplib-dev)");
#endif
}

}  // namespace

int run_cli(int argc, char** argv, LinkedStages stages, TriangleTreeBuilder own_tree,
            const TracingFunctions* contract) {
  CLI::App app{"raylab: a step-by-step ray tracer (course kit)"};
  app.require_subcommand(1);
  RenderOptions options;
  options.own_tree = own_tree;
  CLI::App* render_command = app.add_subcommand("render", "Render a scene file to an image");
  render_command->add_option("scene", options.scene_path, "Scene file (JSON), e.g. scenes/whitted.json")->required();
  render_command->add_option("-o,--output", options.output_path, "Output image: .png, .exr or .ppm")->required();
  render_command->add_option("--width", options.width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 16384));
  render_command->add_option("--height", options.height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 16384));
  render_command->add_option("--max-depth", options.max_depth, "Bounces after the camera ray (default: the scene's, 5)")
      ->check(CLI::Range(0, 64));
  render_command->add_option("--threads", options.threads, "Worker threads (default: one per core this process may use)")
      ->check(CLI::Range(1, 1024));
  render_command->add_option("--spp", options.samples_per_pixel,
                             "Samples per pixel (default 1: one ray through each pixel's centre)")
      ->check(CLI::Range(1, kMaxSamplesPerPixel));
  render_command->add_option("--integrator", options.integrator,
                             "How light is computed (default: the scene's, else whitted): whitted, direct (area and point lights, BSDFs), path "
                             "(path tracing, stage 09) or mis (path tracing with multiple importance sampling, stage 09b)");
  render_command->add_option("--roulette", options.roulette,
                             "path, mis: Russian roulette. A number P in [" + least_roulette_text() +
                                 ", 1]: a path goes on at each bounce with "
                             "chance P (default 1: no roulette, paths end at --max-depth); auto: by the path's "
                             "throughput, from the third surface on (converges faster)");
  render_command->add_option("--seed", options.seed, "Seed of the random numbers (default 0)");
  render_command->add_option("--variance", options.variance_path,
                             "Also write each pixel's variance of the mean (.exr keeps it linear)");
  render_command->add_option("--adaptive", options.adaptive,
                             "Adaptive sampling: stop a pixel's samples (checked every --adaptive-batch) once the 95% confidence "
                             "interval of its mean is within this fraction of it, e.g. 0.05 (--spp: the most a pixel gets)")
      ->check(CLI::Range(0.0001f, 1.0f));
  render_command->add_option("--adaptive-batch", options.adaptive_batch,
                             "With --adaptive: check a pixel after every this many samples (default 32)")
      ->check(CLI::Range(2, kMaxSamplesPerPixel));
  render_command->add_flag("--spp-by-noise", options.samples_by_noise,
                           "--spp is the average: every pixel takes 2 samples, then the rest go where the picture is "
                           "noisiest (the same expected image with fewer samples, each costing more)");
  render_command->add_option("--sample-rate", options.sample_rate_path,
                             "With --adaptive or --spp-by-noise: also write each pixel's samples as a fraction of --spp "
                             "(white: --spp of them)");
  render_command
      ->add_option("--accel", options.accel,
                   "The trees that find the hits: median (stage 05), sah (05b), wide (05c), kdtree (05d), none (every "
                   "primitive), or best (default: the first of wide, sah, kdtree, median whose stages are written and "
                   "that agree with testing every primitive on a sample of rays; the first line says which)")
      ->check(CLI::IsMember(stage_tree_word_list()));
  render_command->add_flag("--watertight", options.watertight,
                           "Use the watertight triangle test (bonus stage 06_robustness) instead of stage 03's");
  render_command->add_flag("-q,--quiet", options.quiet,
                           "No progress (shown on stderr for renders longer than a second or two) and no summary line");
  TraceOptions trace_options;
  TreeBenchOptions bench_options;
  CLI::App* bench_command = app.add_subcommand(
      "bench", "Your trees side by side on a scene: build time, rays per second, nodes and primitives per ray");
  bench_command->add_option("scene", bench_options.scene_path, "Scene file (JSON), e.g. scenes/bunny.json")->required();
  bench_command->add_option("--width", bench_options.width, "Camera rays: one through each pixel of this size (320)")
      ->check(CLI::Range(1, 4096));
  bench_command->add_option("--height", bench_options.height, "(240)")->check(CLI::Range(1, 4096));
  if (stages == LinkedStages::Reference)
    bench_command->add_flag("--save-reference", bench_options.save_reference,
                            "Write the rows into reference_bench.json beside the scene (what raylab bench shows students)");
  CLI::App* trace_command = nullptr;
  if (contract) {
    trace_command = app.add_subcommand(
        "trace", "Trace one pixel: each call of your stage functions along its camera ray, beside the contract's answer");
    trace_command->add_option("scene", trace_options.scene_path, "Scene file (JSON), e.g. scenes/whitted.json")->required();
    trace_command->add_option("--pixel", trace_options.pixel, "The pixel's column and row, from the top left: X Y")
        ->required()
        ->expected(2)
        ->check(CLI::NonNegativeNumber);
    trace_command->add_option("--width", trace_options.width, "As raylab render's (default: the scene's)")
        ->check(CLI::Range(1, 16384));
    trace_command->add_option("--height", trace_options.height, "As raylab render's (default: the scene's)")
        ->check(CLI::Range(1, 16384));
    trace_command->add_option("--sample", trace_options.sample, "Which of the pixel's samples, from 0 (default 0)")
        ->check(CLI::NonNegativeNumber);
    trace_command
        ->add_option("--spp", trace_options.samples_per_pixel,
                     "Samples per pixel of the render traced (default 1): with --sample, the same random numbers")
        ->check(CLI::Range(1, kMaxSamplesPerPixel));
    trace_command->add_option(
        "--integrator", trace_options.integrator,
        "As raylab render's (default: the scene's): direct, path and mis trace the sample's whole path");
    trace_command->add_option("--max-depth", trace_options.max_depth, "As raylab render's (default: the scene's)")
        ->check(CLI::Range(0, 64));
    trace_command->add_option("--roulette", trace_options.roulette, "As raylab render's (default 1: no roulette)");
    trace_command->add_option("--seed", trace_options.seed, "As raylab render's (default 0)");
    trace_command->add_option("--accel", trace_options.accel,
                              "As raylab render's: the tree whose walk is traced (default best: the one render uses)")
        ->check(CLI::IsMember(stage_tree_word_list()));
    trace_command->add_flag("--json", trace_options.json,
                            "Print the trace as JSON (the steps, and the rays as segments on the picture)");
    trace_command
        ->add_option("--lang", trace_options.language, "en or zh: the words of the trace (default en)")
        ->check(CLI::IsMember({"en", "zh"}));
  }

  // raylab view: everything after it goes to the view's server, which has its own --help.
  CLI::App* view_command =
      app.add_subcommand("view", "Watch a scene render in your browser, and trace a pixel by clicking it (raylab view --help)");
  view_command->prefix_command();
  view_command->set_help_flag();
  // raylab view-worker: the view server's renderer; not listed.
  RenderOptions worker_options = options;
  int first_sample = 0, frames_fd = -1;
  bool send_tree = false;
  CLI::App* worker_command = app.add_subcommand("view-worker", "");
  worker_command->group("");
  worker_command->add_option("scene", worker_options.scene_path)->required();
  worker_command->add_option("--frames-fd", frames_fd)->required()->check(CLI::NonNegativeNumber);
  worker_command->add_option("--first-sample", first_sample)->check(CLI::NonNegativeNumber);
  worker_command->add_flag("--tree", send_tree);
  worker_command->add_option("--width", worker_options.width)->check(CLI::Range(1, 16384));
  worker_command->add_option("--height", worker_options.height)->check(CLI::Range(1, 16384));
  worker_command->add_option("--max-depth", worker_options.max_depth)->check(CLI::Range(0, 64));
  worker_command->add_option("--threads", worker_options.threads)->check(CLI::Range(1, 1024));
  worker_command->add_option("--spp", worker_options.samples_per_pixel)->check(CLI::Range(1, kMaxSamplesPerPixel));
  worker_command->add_option("--integrator", worker_options.integrator);
  worker_command->add_option("--roulette", worker_options.roulette);
  worker_command->add_option("--seed", worker_options.seed);
  worker_command->add_option("--adaptive", worker_options.adaptive)->check(CLI::Range(0.0001f, 1.0f));
  worker_command->add_option("--adaptive-batch", worker_options.adaptive_batch)->check(CLI::Range(2, kMaxSamplesPerPixel));
  worker_command->add_flag("--spp-by-noise", worker_options.samples_by_noise);
  worker_command->add_flag("--watertight", worker_options.watertight);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "raylab: " << e.what() << " (see raylab --help)\n";
    return kExitBadInput;
  }

  options.accel_given = render_command->count("--accel") > 0;
  bench_options.reference_program = stages == LinkedStages::Reference;
  bench_options.own_tree = own_tree;
  try {
    if (*render_command) return run_render(options);
    if (*bench_command) return run_tree_bench(bench_options);
    if (trace_command && *trace_command) return run_trace(trace_options, *contract);
    if (*view_command) return run_view(argv[0], view_command->remaining());
    if (*worker_command) return run_view_worker_command(worker_options, first_sample, frames_fd, send_tree);
  } catch (const NotImplemented& e) {
    std::cerr << "raylab: " << e.what() << "\n";
    return kExitNotImplemented;
  } catch (const UsageError& e) {
    std::cerr << "raylab: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const InputError& e) {
    std::cerr << "raylab: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "raylab: error: " << e.what() << "\n";
    return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace raylab
