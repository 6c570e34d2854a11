// stage_calls.h for programs that link stage code: the stage server (the student's or a
// submission's code) and the regenerate tool (the reference solutions).
#include "stage_calls.h"

#include "support.h"

#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/stage_table.h"
#include "raylab/stages/01_camera_rays.h"
#include "raylab/stages/07_sampling.h"
#include "raylab/stages/08_direct_light.h"
#include "raylab/stages/09_path.h"

#include <cmath>

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

std::vector<glm::vec3> direct_light_samples(const DirectLightScene& test_scene, const std::vector<DirectLightQuery>& queries,
                                            std::uint64_t seed) {
  // The test scene: material 0 is the black occluders', then one material per emitter.
  Scene scene;
  scene.materials.push_back(Material{});
  scene.materials[0].kind = MaterialKind::Diffuse;
  scene.materials[0].diffuse_color = glm::vec3(0.0f);
  auto material_of = [&](const glm::vec3& emission) {
    if (emission == glm::vec3(0.0f)) return std::uint32_t{0};
    Material material = scene.materials[0];
    material.emission = emission;
    scene.materials.push_back(material);
    return static_cast<std::uint32_t>(scene.materials.size() - 1);
  };
  for (const DirectLightTriangle& triangle : test_scene.triangles) {
    TriangleMesh mesh;
    mesh.positions = {triangle.p0, triangle.p1, triangle.p2};
    mesh.indices = {0, 1, 2};
    mesh.material = material_of(triangle.emission);
    scene.meshes.push_back(mesh);
  }
  for (const DirectLightSphere& sphere : test_scene.spheres)
    scene.spheres.push_back(Sphere{sphere.center, sphere.radius, material_of(sphere.emission)});
  for (const DirectLightPoint& light : test_scene.point_lights) scene.lights.push_back(PointLight{light.position, light.intensity});
  const SceneGeometry geometry(scene, Acceleration::BruteForce, TriangleTest::MollerTrumbore, grader_tracing());
  const RenderContext context(scene, geometry, 0, Skips{});

  std::vector<glm::vec3> samples;
  Sampler sampler(1, seed);
  int index = 0;
  for (const DirectLightQuery& query : queries) {
    SurfaceHit hit;
    hit.point = query.point;
    // The point is given exactly; a bound on its error keeps shadow rays off the surface.
    hit.point_error = glm::vec3(1e-6f * (1.0f + glm::length(query.point)));
    hit.geometric_normal = query.normal;
    Bsdf bsdf;
    bsdf.kind = BsdfKind::Lambertian;
    bsdf.albedo = query.albedo;
    for (std::uint32_t i = 0; i < query.sample_count; ++i, ++index) {
      sampler.start_pixel_sample(index % 4096, index / 4096, 0);
      samples.push_back(estimate_direct_light(context, hit, bsdf, query.wo, sampler));
    }
  }
  return samples;
}

PathRenderResult path_render(const std::string& scene_path, const PathRenderRequest& request) {
  Scene scene = load_scene(std::string(RAYLAB_SOURCE_DIR) + "/" + scene_path);
  scene.camera.width = request.width;
  scene.camera.height = request.height;
  if (request.albedo >= 0.0f)
    for (Material& material : scene.materials) material.diffuse_color = glm::vec3(request.albedo);
  if (request.probe_only) {
    const SceneGeometry geometry(scene, Acceleration::BruteForce, TriangleTest::MollerTrumbore, grader_tracing());
    const RenderContext context(scene, geometry, request.max_depth, Skips{}, request.roulette_probability);
    Ray ray;
    ray.origin = scene.camera.position;
    ray.direction = glm::normalize(scene.camera.look_at - scene.camera.position);
    Sampler sampler(1, request.seed);
    sampler.start_pixel_sample(0, 0, 0);
    PathRenderResult result{Image(1, 1), Image(1, 1)};
    result.mean.at(0, 0) = path_radiance(context, ray, sampler);
    return result;
  }
  RenderSettings settings;
  settings.integrator = IntegratorKind::Path;
  settings.samples_per_pixel = request.samples_per_pixel;
  settings.max_depth = request.max_depth;
  settings.roulette_probability = request.roulette_probability;
  settings.seed = request.seed;
  settings.track_variance = true;
  settings.tracing = grader_tracing();
  RenderOutput output = render_with_variance(scene, settings);
  return PathRenderResult{std::move(output.mean), std::move(output.variance_of_mean)};
}

}  // namespace raylab::grading
