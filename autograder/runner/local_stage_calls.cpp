// stage_calls.h for programs that link stage code: the stage server (the student's or a
// submission's code) and the regenerate tool (the reference solutions).
#include "stage_calls.h"

#include "support.h"

#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/stage_table.h"
#include "raylab/stages/01_camera_rays.h"

namespace raylab::grading {

std::vector<std::vector<std::uint32_t>> triangles_hit(TriangleFunction function,
                                                      const std::vector<protocol::Triangle>& triangles,
                                                      const std::vector<Ray>& rays,
                                                      const std::vector<std::vector<std::uint32_t>>& candidates) {
  std::vector<std::vector<std::uint32_t>> hits(rays.size());
  for (std::size_t r = 0; r < rays.size(); ++r) {
    auto test = [&](std::uint32_t t) {
      if (function(rays[r], triangles.at(t)[0], triangles.at(t)[1], triangles.at(t)[2])) hits[r].push_back(t);
    };
    if (candidates.empty())
      for (std::uint32_t t = 0; t < triangles.size(); ++t) test(t);
    else
      for (std::uint32_t t : candidates.at(r)) test(t);
  }
  return hits;
}

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
  RenderSettings settings;
  settings.max_depth = scene.max_depth;
  return render(scene, settings);
}

}  // namespace raylab::grading
