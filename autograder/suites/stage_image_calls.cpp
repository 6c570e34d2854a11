// The image test's call between the judge and the stage server (autograder/runner/stage_call.h),
// for every stage with an image in stages.json: the stage's picture (stage_image.h), rendered by
// the stage code in the server, its pixels sent back whole.
#include "grader_geometry.h"
#include "stage_call.h"
#include "stage_image.h"

#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/stage_table.h"
#include "raylab/stages/01_camera_rays.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string_view>

namespace raylab::grading {
namespace {

using protocol::Reader;
using protocol::Writer;

constexpr StageCall kRenderStageImage{"render_stage_image", "rendering the stage's picture",
                                      MessageId::lost_during_stage_picture};

}  // namespace

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

#else
Image render_stage_image(const std::string& stage_id) {
  const StageDescription* stage = find_stage_description(stage_id);
  if (!stage || stage->image_scene.empty())
    throw std::logic_error("stages.json gives the stage " + stage_id + " no image test");
  Scene scene = load_scene(std::string(RAYLAB_SOURCE_DIR) + "/" + std::string(stage->image_scene));
  scene.camera.width = kImageWidth;
  scene.camera.height = kImageHeight;
  if (stage->image_shows == "ray_directions") {
    // Only camera rays: each pixel shows its ray's direction, (d + 1) / 2, as a colour.
    Image image(kImageWidth, kImageHeight);
    for (int y = 0; y < kImageHeight; ++y)
      for (int x = 0; x < kImageWidth; ++x)
        image.at(x, y) = 0.5f * (generate_camera_ray(scene.camera, x, y).direction + 1.0f);
    return image;
  }
  if (stage->image_shows == "spheres") scene.meshes.clear();
  // The picture runs this stage's own functions and the grader's for the rest: its own camera
  // rays, sphere and triangle tests (grader_geometry.h) stand in for those of stages 01-03 but the
  // stage graded, and only stage 05's picture goes through the trees, whose box test is then the
  // grader's own (stages.json: "grader_versions"). So a mistake costs its own stage's picture only.
  const auto has_function = [&](std::string_view function) {
    return std::find(stage->functions.begin(), stage->functions.end(), function) != stage->functions.end();
  };
  RenderSettings settings;
  settings.max_depth = scene.max_depth;
  settings.tracing = grader_tracing();
  if (has_function("intersect_ray_sphere")) settings.tracing.sphere = nullptr;
  if (has_function("intersect_ray_triangle")) settings.tracing.triangle = nullptr;
  settings.tracing.keep_trees = has_function("intersect_bvh");
  return render(scene, settings);
}

namespace {

void serve_render_stage_image(Reader& in, Writer& out) {
  const Image image = render_stage_image(in.get_string());
  out.put<int>(image.width());
  out.put<int>(image.height());
  out.put_vector(image.pixels());
}

const bool kServed = serve(kRenderStageImage, serve_render_stage_image);

}  // namespace
#endif

}  // namespace raylab::grading
