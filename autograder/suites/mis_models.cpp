#include "mis_models.h"

#include "grader_geometry.h"

#include "raylab/bsdf.h"
#include "raylab/geometry.h"
#include "raylab/lights.h"
#include "raylab/scene.h"
#include "raylab/shading.h"

#include <cmath>
#include <optional>
#include <utility>

namespace raylab::grading::mis {

double exact_power(double count_f, double pdf_f, double count_g, double pdf_g) {
  const double f = count_f * pdf_f, g = count_g * pdf_g;
  if (std::isinf(f)) return 1.0;
  if (!(f > 0.0)) return 0.0;
  return f * f / (f * f + g * g);
}

namespace {
const glm::vec3 kFloorAlbedo(0.5f, 0.6f, 0.7f);
const glm::vec3 kLightRadiance(4.0f, 3.0f, 2.0f);
}  // namespace

MisScene quad_light_scene() {
  MisScene scene;
  scene.triangles.push_back({glm::vec3(-8, 0, -8), glm::vec3(-8, 0, 8), glm::vec3(8, 0, 8), glm::vec3(0.0f), kFloorAlbedo});
  scene.triangles.push_back({glm::vec3(-8, 0, -8), glm::vec3(8, 0, 8), glm::vec3(8, 0, -8), glm::vec3(0.0f), kFloorAlbedo});
  const glm::vec3 a(1, 1.5f, -1), b(1, 1.5f, 1), c(-1, 1.5f, 1), d(-1, 1.5f, -1);
  scene.triangles.push_back({a, b, c, kLightRadiance, glm::vec3(0.0f)});  // wound to face down
  scene.triangles.push_back({a, c, d, kLightRadiance, glm::vec3(0.0f)});
  return scene;
}

MisScene point_light_scene() {
  MisScene scene = quad_light_scene();
  scene.triangles.resize(2);  // the floor only
  scene.point_lights.push_back({glm::vec3(0.3f, 2.0f, -0.2f), glm::vec3(5.0f, 4.0f, 3.0f)});
  return scene;
}

// Points and numbers are off every symmetry of the light, so that no BSDF direction meets the edge
// the light's two triangles share (where "the light it hits" would be either).
std::vector<MisScriptedPath> scripted_paths(int max_depth) {
  const glm::vec3 camera(0.0f, 1.0f, -4.0f);
  const glm::vec3 targets[] = {{0.07f, 0.0f, -0.11f}, {0.6f, 0.0f, 0.3f}, {-0.9f, 0.0f, -0.7f}, {1.6f, 0.0f, 1.2f}};
  const float grid_x[] = {0.1f, 0.35f, 0.6f, 0.85f}, grid_y[] = {0.13f, 0.41f, 0.66f, 0.92f};
  std::vector<MisScriptedPath> paths;
  for (const glm::vec3& target : targets)
    for (const float u1 : {0.25f, 0.75f})
      for (const float ux : grid_x)
        for (const float uy : grid_y)
          paths.push_back({camera, glm::normalize(target - camera), u1, glm::vec2(ux, uy), max_depth});
  return paths;
}

const std::vector<ScriptedTest>& scripted_tests() {
  static const std::vector<ScriptedTest> tests = {
      {"LightAndBsdfSamplesWeighted", "a floor under a quad light", "四边形光源下的地面", quad_light_scene(), 2},
      {"PointLightKeepsWeightOne", "a floor under a point light", "点光源下的地面", point_light_scene(), 2},
      {"LastVertexKeepsWeightOne", "a floor under a quad light, max depth 0", "四边形光源下的地面，最大深度 0",
       quad_light_scene(), 0},
  };
  return tests;
}

namespace {

PathParts path_parts(const Scene& scene, const SceneGeometry& geometry, const LightSet& lights, const MisScriptedPath& path) {
  PathParts parts;
  Ray ray;
  ray.origin = path.origin;
  ray.direction = path.direction;
  const std::optional<SurfaceHit> hit = geometry.intersect(ray);
  if (!hit) return parts;
  const Material& material = scene.materials[hit->material];
  const glm::vec3 wo = -glm::normalize(ray.direction);
  const Bsdf bsdf = bsdf_of(material, material.diffuse_color);
  const glm::vec3& normal = hit->geometric_normal;
  if (!lights.empty()) {
    float choice = 0.0f;
    const Light& light = lights[lights.choose(path.u1, &choice)];
    const std::optional<LightSample> sample = sample_li(light, hit->point, path.u2);
    if (sample) {
      const glm::vec3 f = bsdf_f(bsdf, normal, wo, sample->direction);
      Ray shadow;
      shadow.origin = offset_ray_origin(*hit, sample->direction);
      shadow.direction = sample->point - shadow.origin;
      shadow.t_max = 1.0f - 1e-4f;
      if (f != glm::vec3(0.0f) && !geometry.occluded(shadow)) {
        parts.light_pdf = static_cast<double>(sample->pdf) * choice;
        parts.light = f * sample->radiance * static_cast<float>(std::fabs(glm::dot(normal, sample->direction)) / parts.light_pdf);
        parts.light_is_delta = sample->is_delta;
        parts.light_pdf_area = sample->is_delta ? 0.0 : choice / static_cast<double>(light.area);
        parts.bsdf_pdf_of_light = bsdf_pdf(bsdf, normal, wo, sample->direction);
      }
    }
  }
  parts.bsdf_follows = path.max_depth > 0;
  if (!parts.bsdf_follows) return parts;
  const std::optional<BsdfSample> sample = bsdf_sample_f(bsdf, normal, wo, path.u1, path.u2);
  if (!sample) return parts;
  const std::optional<SurfaceHit> next = geometry.intersect(spawn_ray(*hit, sample->wi));
  if (!next) return parts;
  const glm::vec3 emitted = emitted_radiance(scene.materials[next->material], *next, sample->wi);
  if (emitted == glm::vec3(0.0f)) return parts;
  parts.bsdf = sample->f * emitted * static_cast<float>(std::fabs(glm::dot(normal, sample->wi)) / sample->pdf);
  parts.bsdf_pdf = sample->pdf;
  parts.light_pdf_of_bsdf = lights.pdf_li(hit->point, sample->wi);
  // The same density per unit area of the light: pdf_solid_angle cos_light / distance^2.
  const double distance = glm::length(next->point - hit->point);
  const double cos_light = std::fabs(glm::dot(next->geometric_normal, sample->wi));
  parts.light_pdf_area_of_bsdf = parts.light_pdf_of_bsdf * cos_light / (distance * distance);
  return parts;
}

double balance(double f, double g) { return f + g > 0.0 ? f / (f + g) : 0.0; }

MisModel with_flag(bool MisModel::*flag) {
  MisModel model;
  model.*flag = true;
  return model;
}

}  // namespace

std::vector<PathParts> parts_of(const MisScene& test_scene, const std::vector<MisScriptedPath>& paths) {
  const Scene scene = scene_of(test_scene);
  const SceneGeometry geometry(scene, Acceleration::BruteForce, TriangleTest::MollerTrumbore, grader_tracing());
  const LightSet lights(scene);
  std::vector<PathParts> parts;
  for (const MisScriptedPath& path : paths) parts.push_back(path_parts(scene, geometry, lights, path));
  return parts;
}

MisModel both(const MisModel& a, const MisModel& b) {
  return {a.no_mis || b.no_mis, a.balance || b.balance, a.area_pdf || b.area_pdf,
          a.emission_twice || b.emission_twice, a.delta_weighted || b.delta_weighted,
          a.last_vertex_weighted || b.last_vertex_weighted};
}

std::vector<glm::dvec3> model_values(const PathParts& p, const MisModel& model) {
  const auto heuristic = [&](double f, double g) { return model.balance ? balance(f, g) : exact_power(1, f, 1, g); };
  std::vector<double> light_weights, bsdf_weights;
  if (model.no_mis) {
    light_weights = {1.0};
    bsdf_weights = {0.0};
  } else {
    if (p.light_is_delta) {
      // Weighted with the sample's pdf (1 by convention) or with pdf_li (0 for a point light).
      light_weights = model.delta_weighted ? std::vector<double>{heuristic(p.light_pdf, p.bsdf_pdf_of_light), 0.0}
                                           : std::vector<double>{1.0};
    } else if (!p.bsdf_follows) {
      light_weights = {model.last_vertex_weighted ? heuristic(p.light_pdf, p.bsdf_pdf_of_light) : 1.0};
    } else {
      light_weights = {heuristic(p.light_pdf, p.bsdf_pdf_of_light)};
      if (model.area_pdf) light_weights.push_back(heuristic(p.light_pdf_area, p.bsdf_pdf_of_light));
    }
    if (model.emission_twice) light_weights.push_back(1.0);
    bsdf_weights = {model.emission_twice ? 1.0
                    : model.area_pdf     ? heuristic(p.bsdf_pdf, p.light_pdf_area_of_bsdf)
                                         : heuristic(p.bsdf_pdf, p.light_pdf_of_bsdf)};
  }
  const glm::dvec3 light(p.light), bsdf(p.bsdf);
  std::vector<glm::dvec3> values;
  for (const double w_light : light_weights)
    for (const double w_bsdf : bsdf_weights) values.push_back(w_light * light + w_bsdf * bsdf);
  return values;
}

bool same_value(const glm::vec3& got, const glm::dvec3& expected) {
  for (int c = 0; c < 3; ++c)
    if (!(std::fabs(got[c] - expected[c]) <= 2e-3 * std::fabs(expected[c]) + 1e-5)) return false;
  return true;
}

bool fits(const std::vector<glm::vec3>& got, const std::vector<PathParts>& parts, const MisModel& model) {
  for (std::size_t i = 0; i < got.size(); ++i) {
    bool any = false;
    for (const glm::dvec3& value : model_values(parts[i], model)) any = any || same_value(got[i], value);
    if (!any) return false;
  }
  return true;
}

const std::vector<MisMistake>& mis_mistakes() {
  static const std::vector<MisMistake> mistakes = {
      {with_flag(&MisModel::no_mis), MessageId::mis_no_mis, "no MIS"},
      {with_flag(&MisModel::balance), MessageId::mis_balance_weights, "balance heuristic"},
      {with_flag(&MisModel::area_pdf), MessageId::mis_area_pdf_in_weight, "area density in the weight"},
      {with_flag(&MisModel::emission_twice), MessageId::mis_emission_twice, "emission unweighted"},
      {with_flag(&MisModel::delta_weighted), MessageId::mis_delta_weighted, "point light weighted"},
      {with_flag(&MisModel::last_vertex_weighted), MessageId::mis_last_vertex_weighted, "last vertex weighted"},
  };
  return mistakes;
}

MisFit fit_mistakes(const std::vector<glm::vec3>& got, const std::vector<PathParts>& parts) {
  const std::vector<MisMistake>& mistakes = mis_mistakes();
  MisFit fit;
  for (const MisMistake& mistake : mistakes)
    if (fits(got, parts, mistake.model)) fit.named.push_back(&mistake);
  if (!fit.named.empty()) return fit;
  std::vector<std::pair<const MisMistake*, const MisMistake*>> fitting;
  for (std::size_t i = 0; i < mistakes.size(); ++i)
    for (std::size_t j = i + 1; j < mistakes.size(); ++j)
      if (fits(got, parts, both(mistakes[i].model, mistakes[j].model))) fitting.emplace_back(&mistakes[i], &mistakes[j]);
  if (fitting.size() == 1) fit = {{fitting[0].first, fitting[0].second}, true};
  return fit;
}

}  // namespace raylab::grading::mis
