// Stage 09's calls between the judge and the stage server (autograder/runner/stage_call.h): only
// whole pictures rendered with path_radiance (path_render), each pixel's mean and its variance;
// the bonus stage 09b renders with path_radiance_mis through the same call (request.mis).
#include "09_path_calls.h"
#include "kit_folders.h"
#include "grader_geometry.h"
#include "stage_call.h"
#include "stage_image.h"

#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/stages/09_path.h"
#include "raylab/stages/09b_mis.h"
#include "raylab/testkit/exact_tracing.h"

#include <algorithm>

#include <cstring>
#include <stdexcept>

namespace raylab {
namespace {

using grading::PathRenderRequest;
using grading::PathRenderResult;
using grading::protocol::Reader;
using grading::protocol::Writer;

constexpr grading::StageCall kPathRender{"path_render", "path_radiance (rendering)",
                                         grading::MessageId::lost_during_path_rendering};
constexpr grading::StageCall kPathMisRender{"path_mis_render", "path_radiance_mis (rendering)",
                                            grading::MessageId::lost_during_path_mis_rendering};
constexpr grading::StageCall kPathTracePixel{"path_trace_pixel", "tracing a pixel of the path tracer's picture",
                                             grading::MessageId::lost_during_stage_picture_trace};

// The trace's settings for the picture of `request`, its sample left at 0.
TraceSettings path_trace_settings(const PathRenderRequest& request, bool chinese) {
  TraceSettings settings;
  settings.integrator = request.mis ? IntegratorKind::PathMis : IntegratorKind::Path;
  settings.samples_per_pixel = request.samples_per_pixel;
  settings.seed = request.seed;
  settings.max_depth = request.max_depth;
  settings.roulette = RussianRoulette{request.roulette_probability, false};
  settings.chinese = chinese;
  return settings;
}

}  // namespace

#if RAYLAB_JUDGE
glm::vec3 path_radiance(const RenderContext&, const Ray&, Sampler&) {
  throw std::logic_error("the judge calls path_radiance only through grading::path_render");
}

namespace grading {

PathRenderResult path_render(const std::string& scene_path, const PathRenderRequest& request) {
  Writer arguments;
  arguments.put_string(scene_path);
  arguments.put(request);
  return remote(request.mis ? kPathMisRender : kPathRender, arguments, [&](Reader& in) {
    const int width = in.get<int>(), height = in.get<int>();
    const auto mean = in.get_vector<glm::vec3>();
    const auto variance = in.get_vector<glm::vec3>();
    in.expect_end();
    const int expected_width = request.probe_only ? 1 : request.width;
    const int expected_height = request.probe_only ? 1 : request.height;
    const std::size_t pixels = static_cast<std::size_t>(expected_width) * static_cast<std::size_t>(expected_height);
    if (width != expected_width || height != expected_height || mean.size() != pixels || variance.size() != pixels)
      throw protocol::ProtocolError(MessageId::protocol_wrong_picture_size);
    PathRenderResult result{Image(width, height), Image(width, height)};
    std::memcpy(result.mean.data(), mean.data(), pixels * sizeof(glm::vec3));
    std::memcpy(result.variance_of_mean.data(), variance.data(), pixels * sizeof(glm::vec3));
    return result;
  }, {}, reply_limit(2 * sizeof(int) + 2 * sizeof(std::uint64_t) + 2 * sizeof(glm::vec3) * (request.probe_only ? 1 :
                     static_cast<std::uint64_t>(std::max(request.width, 0)) * static_cast<std::uint64_t>(std::max(request.height, 0)))));
}

PixelTrace path_trace_pixel(const std::string& scene_path, const PathRenderRequest& request, int x, int y,
                            bool chinese) {
  const StageSession::DiagnosticCalls diagnostic(kTraceSeconds);
  Writer arguments;
  arguments.put_string(scene_path);
  arguments.put(request);
  arguments.put<int>(x);
  arguments.put<int>(y);
  arguments.put<std::uint8_t>(chinese);
  return remote(kPathTracePixel, arguments, [&](Reader& in) {
    PixelTrace trace;
    trace.x = x;
    trace.y = y;
    trace.settings = path_trace_settings(request, chinese);
    // Shown, never believed: a sample outside the pixel's is a malformed reply (no trace).
    const int sample = in.get<int>();
    if (sample < 0 || sample >= request.samples_per_pixel) throw protocol::ProtocolError(MessageId::protocol_malformed_lists);
    trace.settings.sample = sample;
    read_trace_steps(in, trace);
    in.expect_end();
    return trace;
  }, {}, reply_limit(1u << 20));
}

}  // namespace grading

#else
namespace grading {

// The scene of a request: its size, and the test's changes (a grey albedo, a background).
Scene request_scene(const std::string& scene_path, const PathRenderRequest& request) {
  Scene scene = load_scene(std::string(kit_source_folder()) + "/" + scene_path);
  scene.camera.width = request.width;
  scene.camera.height = request.height;
  if (request.albedo >= 0.0f)
    for (Material& material : scene.materials) material.diffuse_color = glm::vec3(request.albedo);
  if (request.background.x >= 0.0f && request.background.y >= 0.0f && request.background.z >= 0.0f)
    scene.background = request.background;
  return scene;
}

PathRenderResult path_render(const std::string& scene_path, const PathRenderRequest& request) {
  const Scene scene = request_scene(scene_path, request);
  if (request.probe_only) {
    const SceneGeometry geometry(scene, Acceleration::BruteForce, TriangleTest::MollerTrumbore, grader_tracing());
    const RenderContext context(scene, geometry, request.max_depth, Skips{},
                                RussianRoulette{request.roulette_probability, false});
    Ray ray;
    ray.origin = scene.camera.position;
    ray.direction = glm::normalize(scene.camera.look_at - scene.camera.position) * (request.probe_away ? -1.0f : 1.0f);
    Sampler sampler(1, request.seed);
    sampler.start_pixel_sample(0, 0, 0);
    PathRenderResult result{Image(1, 1), Image(1, 1)};
    result.mean.at(0, 0) = request.mis ? path_radiance_mis(context, ray, sampler) : path_radiance(context, ray, sampler);
    return result;
  }
  RenderSettings settings;
  settings.integrator = request.mis ? IntegratorKind::PathMis : IntegratorKind::Path;
  settings.samples_per_pixel = request.samples_per_pixel;
  settings.max_depth = request.max_depth;
  settings.roulette = RussianRoulette{request.roulette_probability, false};
  settings.seed = request.seed;
  settings.track_variance = true;
  settings.tracing = grader_tracing();
  RenderOutput output = render_with_variance(scene, settings);
  return PathRenderResult{std::move(output.mean), std::move(output.variance_of_mean)};
}

PixelTrace path_trace_pixel(const std::string& scene_path, const PathRenderRequest& request, int x, int y,
                            bool chinese) {
  const Scene scene = request_scene(scene_path, request);
  TraceSettings settings = path_trace_settings(request, chinese);
  settings.yours = grader_tracing();  // as path_render's picture: the grader's geometry
  std::optional<PixelTrace> first;
  for (int sample = 0; sample < std::min(request.samples_per_pixel, kMostTracedPathSamples); ++sample) {
    settings.sample = sample;
    PixelTrace trace = trace_pixel(scene, x, y, settings, testkit::exact_tracing());
    if (trace.first_disagreement() >= 0) return trace;
    if (!first) first = std::move(trace);
  }
  if (!first) throw std::invalid_argument("the picture has no samples to trace");
  return *first;
}

}  // namespace grading

namespace {

void serve_path_render(Reader& in, Writer& out) {
  const std::string scene_path = in.get_string();
  const auto request = in.get<PathRenderRequest>();
  const PathRenderResult result = grading::path_render(scene_path, request);
  out.put<int>(result.mean.width());
  out.put<int>(result.mean.height());
  out.put_vector(result.mean.pixels());
  out.put_vector(result.variance_of_mean.pixels());
}

void serve_path_trace_pixel(Reader& in, Writer& out) {
  const std::string scene_path = in.get_string();
  const auto request = in.get<PathRenderRequest>();
  const int x = in.get<int>(), y = in.get<int>();
  const bool chinese = in.get<std::uint8_t>() != 0;
  const PixelTrace trace = grading::path_trace_pixel(scene_path, request, x, y, chinese);
  out.put<int>(trace.settings.sample);
  grading::write_trace_steps(out, trace);
}

const bool kServed = grading::serve(kPathRender, serve_path_render) && grading::serve(kPathMisRender, serve_path_render) &&
                     grading::serve(kPathTracePixel, serve_path_trace_pixel);

}  // namespace
#endif

}  // namespace raylab
