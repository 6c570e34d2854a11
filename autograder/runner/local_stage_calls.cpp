// stage_calls.h for programs that link stage code: the stage server (the student's or a
// submission's code) and the regenerate tool (the reference solutions).
#include "stage_calls.h"

#include "support.h"

#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/stage_table.h"
#include "raylab/stages/01_camera_rays.h"
#include "raylab/stages/07_sampling.h"

#include <stdexcept>

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

std::vector<glm::vec3> warp_samples(Warp warp, const std::vector<glm::vec2>& uniform_randoms) {
  std::vector<glm::vec3> samples;
  samples.reserve(uniform_randoms.size());
  for (const glm::vec2& u : uniform_randoms) {
    switch (warp) {
      case Warp::UniformHemisphere: samples.push_back(sample_uniform_hemisphere(u)); break;
      case Warp::CosineHemisphere: samples.push_back(sample_cosine_hemisphere(u)); break;
      case Warp::UniformSphere: samples.push_back(sample_uniform_sphere(u)); break;
      case Warp::UniformDisk: samples.push_back(glm::vec3(sample_uniform_disk(u), 0.0f)); break;
      case Warp::UniformTriangle: {
        const Barycentrics b = sample_uniform_triangle(u);
        samples.push_back(glm::vec3(b.barycentric_b1, b.barycentric_b2, 0.0f));
        break;
      }
      default: throw std::invalid_argument("warp_samples: no such warp");
    }
  }
  return samples;
}

std::vector<float> warp_pdfs(Warp warp, const std::vector<glm::vec3>& arguments) {
  std::vector<float> values;
  if (warp == Warp::UniformTriangle) {
    if (arguments.size() % 3 != 0) throw std::invalid_argument("warp_pdfs: three corners per triangle");
    for (std::size_t i = 0; i < arguments.size(); i += 3)
      values.push_back(uniform_triangle_pdf(arguments[i], arguments[i + 1], arguments[i + 2]));
    return values;
  }
  values.reserve(arguments.size());
  for (const glm::vec3& argument : arguments) {
    switch (warp) {
      case Warp::UniformHemisphere: values.push_back(uniform_hemisphere_pdf(argument)); break;
      case Warp::CosineHemisphere: values.push_back(cosine_hemisphere_pdf(argument)); break;
      case Warp::UniformSphere: values.push_back(uniform_sphere_pdf(argument)); break;
      case Warp::UniformDisk: values.push_back(uniform_disk_pdf(glm::vec2(argument))); break;
      default: throw std::invalid_argument("warp_pdfs: no such warp");
    }
  }
  return values;
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
