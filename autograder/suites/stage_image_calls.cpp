// The image test's call between the judge and the stage server (autograder/runner/stage_call.h),
// for every stage with an image in stages.json: the stage's picture (stage_image.h), rendered by
// the stage code in the server, its pixels sent back whole.
#include "grader_geometry.h"
#include "kit_folders.h"
#include "stage_call.h"
#include "stage_image.h"

#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/stage_table.h"
#include "raylab/stages/01_camera_rays.h"
#include "raylab/testkit/exact_tracing.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string_view>

namespace raylab::grading {
namespace {

using protocol::Reader;
using protocol::Writer;

constexpr StageCall kRenderStageImage{"render_stage_image", "rendering the stage's picture",
                                      MessageId::lost_during_stage_picture};
constexpr StageCall kTraceStageImagePixel{"trace_stage_image_pixel", "tracing a pixel of the stage's picture",
                                          MessageId::lost_during_stage_picture_trace};

}  // namespace

std::string stage_image_trace_command(const std::string& stage_id, int x, int y, bool chinese) {
  const StageDescription* stage = find_stage_description(stage_id);
  return std::string("build/bin/raylab trace ") + (chinese ? "--lang zh " : "") + "--width " +
         std::to_string(kImageWidth) + " --height " + std::to_string(kImageHeight) + " --pixel " + std::to_string(x) +
         " " + std::to_string(y) + " " + (stage ? std::string(stage->image_scene) : std::string("SCENE"));
}

void write_trace_steps(Writer& out, const PixelTrace& trace) {
  const std::size_t sent = std::min(trace.steps.size(), kMostTracedSteps);
  out.put<std::uint32_t>(static_cast<std::uint32_t>(std::min<std::size_t>(trace.steps.size(), UINT32_MAX)));
  out.put<std::uint32_t>(static_cast<std::uint32_t>(sent));
  const auto cut = [](const std::string& text) { return protocol::cut_text(text, kMostTracedTextBytes, " [...]"); };
  for (std::size_t i = 0; i < sent; ++i) {
    const TraceStep& step = trace.steps[i];
    for (const std::string* text : {&step.stage, &step.function, &step.call, &step.yours, &step.expected, &step.note})
      out.put_string(cut(*text));
    out.put<std::uint8_t>(step.agrees);
  }
  out.put<int>(trace.untouched_spheres);
  out.put<int>(trace.untouched_triangles);
}

void read_trace_steps(Reader& in, PixelTrace& trace) {
  const auto total = in.get<std::uint32_t>(), count = in.get<std::uint32_t>();
  trace.steps_cut = total > count || count > kMostTracedSteps;
  const auto cut = [](const std::string& text) { return protocol::cut_text(text, kMostTracedTextBytes, " [...]"); };
  for (std::uint32_t i = 0; i < count; ++i) {
    std::string stage = in.get_string(), function = in.get_string(), call = in.get_string(), yours = in.get_string(),
                expected = in.get_string(), note = in.get_string();
    const bool agrees = in.get<std::uint8_t>() != 0;
    if (trace.steps.size() < kMostTracedSteps)
      trace.steps.emplace_back(cut(stage), cut(function), cut(call), cut(yours), cut(expected), cut(note), agrees);
  }
  trace.untouched_spheres = in.get<int>();
  trace.untouched_triangles = in.get<int>();
}

#if RAYLAB_JUDGE
Image render_stage_image(const std::string& stage_id) {
  Writer arguments;
  arguments.put_string(stage_id);
  return remote(kRenderStageImage, arguments, [](Reader& in) {
    const int width = in.get<int>(), height = in.get<int>();
    const auto pixels = in.get_vector<glm::vec3>();
    in.expect_end();
    if (width != kImageWidth || height != kImageHeight ||
        pixels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
      throw protocol::ProtocolError(MessageId::protocol_wrong_picture_size);
    Image image(width, height);
    std::memcpy(image.data(), pixels.data(), pixels.size() * sizeof(glm::vec3));
    return image;
  }, {}, reply_limit(2 * sizeof(int) + sizeof(std::uint64_t) + std::uint64_t{kImageWidth} * kImageHeight * sizeof(glm::vec3)));
}

PixelTrace trace_stage_image_pixel(const std::string& stage_id, int x, int y, bool chinese) {
  const StageSession::DiagnosticCalls diagnostic(kTraceSeconds);
  Writer arguments;
  arguments.put_string(stage_id);
  arguments.put<int>(x);
  arguments.put<int>(y);
  arguments.put<std::uint8_t>(chinese);
  return remote(kTraceStageImagePixel, arguments, [&](Reader& in) {
    PixelTrace trace;
    trace.x = x;
    trace.y = y;
    read_trace_steps(in, trace);
    in.expect_end();
    return trace;
  }, {}, reply_limit(1u << 20));
}

#else
// The scene and settings of a stage's picture (stages.json: "image").
struct StageImageSetup {
  Scene scene;
  RenderSettings settings;
};
StageImageSetup stage_image_setup(const std::string& stage_id) {
  const StageDescription* stage = find_stage_description(stage_id);
  if (!stage || stage->image_scene.empty())
    throw std::logic_error("stages.json gives the stage " + stage_id + " no image test");
  StageImageSetup setup{load_scene(std::string(kit_source_folder()) + "/" + std::string(stage->image_scene)), {}};
  Scene& scene = setup.scene;
  scene.camera.width = kImageWidth;
  scene.camera.height = kImageHeight;
  if (stage->image_shows == "ray_directions") {  // only the camera rays: nothing is hit
    scene.spheres.clear();
    scene.meshes.clear();
    return setup;
  }
  if (stage->image_shows == "spheres") scene.meshes.clear();
  // The picture runs this stage's own functions and the grader's for the rest: its own camera
  // rays, sphere and triangle tests (grader_geometry.h) stand in for those of stages 01-03 but the
  // stage graded, and only stage 05's picture goes through the trees, whose box test is then the
  // grader's own (stages.json: "grader_versions"). So a mistake costs its own stage's picture only.
  const auto has_function = [&](std::string_view function) {
    return std::find(stage->functions.begin(), stage->functions.end(), function) != stage->functions.end();
  };
  RenderSettings& settings = setup.settings;
  settings.max_depth = scene.max_depth;
  settings.tracing = grader_tracing();
  if (has_function("intersect_ray_sphere")) settings.tracing.sphere = nullptr;
  if (has_function("intersect_ray_triangle")) settings.tracing.triangle = nullptr;
  settings.tracing.keep_trees = has_function("intersect_bvh");
  return setup;
}

Image render_stage_image(const std::string& stage_id) {
  const StageImageSetup setup = stage_image_setup(stage_id);
  if (find_stage_description(stage_id)->image_shows == "ray_directions") {
    // Each pixel shows its camera ray's direction, (d + 1) / 2, as a colour.
    Image image(kImageWidth, kImageHeight);
    for (int y = 0; y < kImageHeight; ++y)
      for (int x = 0; x < kImageWidth; ++x)
        image.at(x, y) = 0.5f * (generate_camera_ray(setup.scene.camera, x, y).direction + 1.0f);
    return image;
  }
  return render(setup.scene, setup.settings);
}

PixelTrace trace_stage_image_pixel(const std::string& stage_id, int x, int y, bool chinese) {
  const StageImageSetup setup = stage_image_setup(stage_id);
  TraceSettings settings;
  settings.chinese = chinese;
  settings.max_depth = setup.settings.max_depth;
  settings.yours = setup.settings.tracing;
  return trace_pixel(setup.scene, x, y, settings, testkit::exact_tracing());
}

namespace {

void serve_render_stage_image(Reader& in, Writer& out) {
  const Image image = render_stage_image(in.get_string());
  out.put<int>(image.width());
  out.put<int>(image.height());
  out.put_vector(image.pixels());
}

const bool kServed = serve(kRenderStageImage, serve_render_stage_image);

void serve_trace_stage_image_pixel(Reader& in, Writer& out) {
  const std::string stage_id = in.get_string();
  const int x = in.get<int>(), y = in.get<int>();
  const bool chinese = in.get<std::uint8_t>() != 0;
  write_trace_steps(out, trace_stage_image_pixel(stage_id, x, y, chinese));
}

const bool kTraceServed = serve(kTraceStageImagePixel, serve_trace_stage_image_pixel);

}  // namespace
#endif

}  // namespace raylab::grading
