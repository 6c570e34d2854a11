// Autograder suite for the bonus stage 09b_mis (30 points).
//
// power_heuristic is judged against exact values, each wrong value checked against the mistakes
// that explain it. path_radiance_mis is judged twice:
//   Is it MIS? Scripted paths (09b_mis_calls.h: mis_scripted_paths): the stage server traces
//   chosen rays in a small test scene (a floor under a quad light, or under a point light) with a
//   constant sampler, so the judge knows the light point and the BSDF direction each path takes.
//   The judge computes both samples itself, with the framework's sample_li, bsdf_sample_f, pdf_li
//   and bsdf_pdf (which call the grader's own stages 07 and 08, as your path does here: stages.json,
//   "grader_versions"), and the value a correct
//   MIS path tracer returns: each sample's contribution times its power-heuristic weight. The
//   models of the common mistakes (no MIS, the balance heuristic, an area density in the weight,
//   the emission unweighted, a weighted point light, a weighted last vertex) are fitted to every
//   path: a model that explains every value is named. These tests are exact (float tolerance).
//   Is it unbiased? Two furnaces t-tested against their exact answer and the two Cornell boxes
//   z-tested region by region against stage 09's converged reference (path_support.h), as in
//   stage 09: an ordinary path tracer without MIS passes these and loses the scripted tests.
//
// False failures: the 2 furnace t-tests, their 2 spread tests, the test of short paths of the
// furnace with roulette (path_support.h) and the 2 x 64 x 3 region z-tests share
// kGraderFalseFailureRate (1 in 1,000 for the stage, Sidak-corrected: mis_test_level()); the
// exact tests have tolerances that a correct implementation never exceeds.
// autograder-false-failures --stage 09b_mis measures it.
#include "09b_mis_calls.h"
#include "grader_geometry.h"
#include "grading.h"
#include "path_support.h"
#include "support.h"

#include "raylab/bsdf.h"
#include "raylab/error.h"
#include "raylab/geometry.h"
#include "raylab/lights.h"
#include "raylab/shading.h"
#include "raylab/stages/09b_mis.h"
#include "raylab/testkit/statistics.h"

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "09b_mis";
const double kLevel = mis_test_level();

// Not attempted only when both functions are the stub.
const bool kRegistered = register_stage(kStage, [] {
  throw_if_every_function_is_a_stub(
      kStage, {[] { (void)power_heuristic(1, 1.0f, 1, 1.0f); },
               [] {
                 MisScene scene;
                 scene.triangles.push_back(
                     {glm::vec3(-1, 0, -1), glm::vec3(-1, 0, 1), glm::vec3(1, 0, 0), glm::vec3(0.0f), glm::vec3(0.5f)});
                 (void)mis_scripted_paths(scene, {MisScriptedPath{glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), 0.5f,
                                                                  glm::vec2(0.5f), 0}});
               }});
});

// ---- power_heuristic -----------------------------------------------------------------------

double exact_power(double count_f, double pdf_f, double count_g, double pdf_g) {
  const double f = count_f * pdf_f, g = count_g * pdf_g;
  if (std::isinf(f)) return 1.0;
  if (!(f > 0.0)) return 0.0;
  return f * f / (f * f + g * g);
}

struct HeuristicCase {
  int count_f;
  float pdf_f;
  int count_g;
  float pdf_g;
};

std::string call_text(const HeuristicCase& c) {
  return "power_heuristic(" + std::to_string(c.count_f) + ", " + gtest_text(c.pdf_f) + ", " + std::to_string(c.count_g) +
         ", " + gtest_text(c.pdf_g) + ")";
}

bool close(double got, double expected, double relative) {
  return std::fabs(got - expected) <= relative * std::fabs(expected) + 1e-7;
}

// The weights of the common mistakes, for densities f = n_f pdf_f > 0 and g = n_g pdf_g, both finite.
struct HeuristicMistake {
  MessageId hint;
  double (*weight)(const HeuristicCase&);
};
double sq(double x) { return x * x; }
const HeuristicMistake kHeuristicMistakes[] = {
    {MessageId::mis_heuristic_balance,
     [](const HeuristicCase& c) { return 1.0 * c.count_f * c.pdf_f / (1.0 * c.count_f * c.pdf_f + 1.0 * c.count_g * c.pdf_g); }},
    {MessageId::mis_heuristic_counts_ignored,
     [](const HeuristicCase& c) { return sq(c.pdf_f) / (sq(c.pdf_f) + sq(c.pdf_g)); }},
    {MessageId::mis_heuristic_counts_outside,
     [](const HeuristicCase& c) { return c.count_f * sq(c.pdf_f) / (c.count_f * sq(c.pdf_f) + c.count_g * sq(c.pdf_g)); }},
    {MessageId::mis_heuristic_other_weight,
     [](const HeuristicCase& c) { return 1.0 - exact_power(c.count_f, c.pdf_f, c.count_g, c.pdf_g); }},
};

// Checks the cases; on the first wrong value adds the failure and the hints that explain it: NaN
// from an edge case, or a mistake whose weights match every ordinary case (both densities finite,
// f's above 0) of the list.
void expect_heuristic(const std::vector<HeuristicCase>& cases) {
  std::vector<float> got;
  for (const HeuristicCase& c : cases) got.push_back(power_heuristic(c.count_f, c.pdf_f, c.count_g, c.pdf_g));
  auto ordinary = [](const HeuristicCase& c) { return c.pdf_f > 0.0f && std::isfinite(c.pdf_f) && std::isfinite(c.pdf_g); };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const HeuristicCase& c = cases[i];
    const double expected = exact_power(c.count_f, c.pdf_f, c.count_g, c.pdf_g);
    if (close(got[i], expected, 1e-5)) continue;
    add_failure({MessageId::mis_failure_value,
                 {{"call", call_text(c)}, {"got", gtest_text(got[i])}, {"expected", gtest_text(expected)}}});
    if (!std::isfinite(got[i])) {
      if (std::isinf(c.pdf_f) || std::isinf(c.pdf_g)) add_hint({MessageId::mis_heuristic_infinite, {}});
      else if (c.pdf_f == 0.0f && c.pdf_g == 0.0f) add_hint({MessageId::mis_heuristic_zero_nan, {}});
      return;
    }
    if (!ordinary(c)) return;  // an edge case: the failure says enough
    for (const HeuristicMistake& mistake : kHeuristicMistakes) {
      bool fits_all = true;
      for (std::size_t j = 0; j < cases.size() && fits_all; ++j)
        if (ordinary(cases[j])) fits_all = close(got[j], mistake.weight(cases[j]), 1e-4);
      if (fits_all) add_hint({mistake.hint, {}});
    }
    return;
  }
}

GRADED_TEST(kStage, Stage09bMis, PowerHeuristicValues, 4) {
  // The handout's worked number first (1 and 3: 0.9), then uneven densities and counts.
  expect_heuristic({{1, 3.0f, 1, 1.0f},
                    {1, 1.0f, 1, 1.0f},
                    {1, 1.0f, 1, 3.0f},
                    {1, 0.05f, 1, 0.318f},
                    {2, 1.0f, 1, 1.0f},
                    {1, 2.0f, 3, 1.0f},
                    {4, 0.25f, 1, 12.5f}});
}

GRADED_TEST(kStage, Stage09bMis, PowerHeuristicEdgeCases, 3) {
  // A density of 0 (the other strategy cannot make this sample), both 0 (0, not 0 / 0), and an
  // infinite density (a delta: only it can make the sample).
  const float infinity = std::numeric_limits<float>::infinity();
  expect_heuristic({{1, 2.0f, 1, 0.0f},
                    {1, 0.0f, 1, 2.0f},
                    {1, 0.0f, 1, 0.0f},
                    {1, infinity, 1, 0.5f},
                    {1, 0.5f, 1, infinity},
                    {1, 1e-20f, 1, 1e-20f}});
}

// ---- Scripted paths -------------------------------------------------------------------------

// The test scenes: a floor (y = 0, facing up) under a quad light (two triangles facing down,
// black: a path that reaches it ends there), or under a point light. Nothing else: a BSDF sample
// that misses the light leaves the scene.
const glm::vec3 kFloorAlbedo(0.5f, 0.6f, 0.7f);
const glm::vec3 kLightRadiance(4.0f, 3.0f, 2.0f);

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

// Paths from a camera in front of the floor to points on it, for every pair of numbers of a grid.
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

// What a path of the test scenes is made of, computed by the judge: the light sample at the floor
// point and the light the BSDF sample finds, each before its weight, with the densities the
// weights compare. Computed with the framework's light and BSDF sampling, which call the grader's
// own stages 07 and 08 (as the student's path does here): this stage is judged on its weights only.
struct PathParts {
  glm::vec3 light{0.0f};  // f L |cos| / pdf of the light sample (0: none, or blocked)
  bool light_is_delta = false;
  double light_pdf = 0, light_pdf_area = 0, bsdf_pdf_of_light = 0;
  bool bsdf_follows = false;
  glm::vec3 bsdf{0.0f};  // f |cos| / pdf times the emission the BSDF sample finds (0: none)
  double bsdf_pdf = 0, light_pdf_of_bsdf = 0, light_pdf_area_of_bsdf = 0;
};

PathParts parts_of(const Scene& scene, const SceneGeometry& geometry, const LightSet& lights, const MisScriptedPath& path) {
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

// How a path tracer weighs the two samples: the correct one, changed by the common mistakes, each
// a flag, so that two mistakes made together are both flags.
struct MisModel {
  bool no_mis = false;                // the light sample alone, weight 1
  bool balance = false;               // the balance heuristic f / (f + g)
  bool area_pdf = false;              // the light's density per unit area in the BSDF sample's weight (or in both)
  bool emission_twice = false;        // the BSDF sample's emission with weight 1
  bool delta_weighted = false;        // a point light's sample weighted like an area light's
  bool last_vertex_weighted = false;  // the light sample at the last vertex weighted, no BSDF sample following
};
MisModel both(const MisModel& a, const MisModel& b) {
  return {a.no_mis || b.no_mis, a.balance || b.balance, a.area_pdf || b.area_pdf,
          a.emission_twice || b.emission_twice, a.delta_weighted || b.delta_weighted,
          a.last_vertex_weighted || b.last_vertex_weighted};
}

double balance(double f, double g) { return f + g > 0.0 ? f / (f + g) : 0.0; }

// The values `model` may give for the path (a mistake can be made in more than one way): every
// weight of the light sample it may use, with every weight of the BSDF sample.
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

bool close(const glm::vec3& got, const glm::dvec3& expected) {
  for (int c = 0; c < 3; ++c)
    if (!(std::fabs(got[c] - expected[c]) <= 2e-3 * std::fabs(expected[c]) + 1e-5)) return false;
  return true;
}

bool fits(const std::vector<glm::vec3>& got, const std::vector<PathParts>& parts, const MisModel& model) {
  for (std::size_t i = 0; i < got.size(); ++i) {
    bool any = false;
    for (const glm::dvec3& value : model_values(parts[i], model)) any = any || close(got[i], value);
    if (!any) return false;
  }
  return true;
}

// A test scene's name in the failure texts, in English and Chinese.
struct SceneName {
  std::string english, chinese;
  MessageArg arg() const { return MessageArg::bilingual("what", english, chinese); }
};

// The common mistakes, each as the flag of MisModel it sets, with its hint.
struct MisMistake {
  MisModel model;
  MessageId hint;
};
MisModel with_flag(bool MisModel::*flag) {
  MisModel model;
  model.*flag = true;
  return model;
}
const std::vector<MisMistake>& mis_mistakes() {
  static const std::vector<MisMistake> mistakes = {
      {with_flag(&MisModel::no_mis), MessageId::mis_no_mis},
      {with_flag(&MisModel::balance), MessageId::mis_balance_weights},
      {with_flag(&MisModel::area_pdf), MessageId::mis_area_pdf_in_weight},
      {with_flag(&MisModel::emission_twice), MessageId::mis_emission_twice},
      {with_flag(&MisModel::delta_weighted), MessageId::mis_delta_weighted},
      {with_flag(&MisModel::last_vertex_weighted), MessageId::mis_last_vertex_weighted},
  };
  return mistakes;
}

// Traces the paths with the student's path_radiance_mis and compares every value with the judge's;
// names the first that differs and the mistakes whose model explains every value: one, or when
// no single one does and exactly one pair does, two made together.
void expect_scripted(const SceneName& what, const MisScene& test_scene, const std::vector<MisScriptedPath>& paths) {
  const std::vector<glm::vec3> got = mis_scripted_paths(test_scene, paths);
  const Scene scene = scene_of(test_scene);
  const SceneGeometry geometry(scene, Acceleration::BruteForce, TriangleTest::MollerTrumbore, grader_tracing());
  const LightSet lights(scene);
  std::vector<PathParts> parts;
  for (const MisScriptedPath& path : paths) parts.push_back(parts_of(scene, geometry, lights, path));
  for (std::size_t i = 0; i < got.size(); ++i) {
    const glm::vec3& v = got[i];
    if (hint_if_not_finite("path_radiance_mis", {v.x, v.y, v.z}, {MessageId::mis_advice_division, {}})) {
      add_failure({MessageId::mis_failure_not_finite, {what.arg()}});
      return;
    }
  }
  std::size_t wrong = got.size();
  for (std::size_t i = 0; i < got.size() && wrong == got.size(); ++i)
    if (!close(got[i], model_values(parts[i], MisModel{})[0])) wrong = i;
  if (wrong == got.size()) return;
  const MisScriptedPath& path = paths[wrong];
  const PathParts& p = parts[wrong];
  add_failure({MessageId::mis_failure_path,
               {what.arg(),
                {"origin", gtest_text(path.origin)},
                {"direction", gtest_text(path.direction)},
                {"u1", gtest_text(path.u1)},
                {"u2", gtest_text(path.u2)},
                {"depth", std::to_string(path.max_depth)},
                {"expected", gtest_text(glm::vec3(model_values(p, MisModel{})[0]))},
                {"got", gtest_text(got[wrong])},
                {"light", gtest_text(p.light)},
                {"light_pdf", gtest_text(p.light_pdf)},
                {"light_bsdf_pdf", gtest_text(p.bsdf_pdf_of_light)},
                {"bsdf", gtest_text(p.bsdf)},
                {"bsdf_pdf", gtest_text(p.bsdf_pdf)},
                {"bsdf_light_pdf", gtest_text(p.light_pdf_of_bsdf)}}});
  const std::vector<MisMistake>& mistakes = mis_mistakes();
  bool named = false;
  for (const MisMistake& mistake : mistakes)
    if (fits(got, parts, mistake.model)) {
      add_hint({mistake.hint, {}});
      named = true;
    }
  if (named) return;
  std::vector<std::pair<const MisMistake*, const MisMistake*>> fitting;
  for (std::size_t i = 0; i < mistakes.size(); ++i)
    for (std::size_t j = i + 1; j < mistakes.size(); ++j)
      if (fits(got, parts, both(mistakes[i].model, mistakes[j].model))) fitting.emplace_back(&mistakes[i], &mistakes[j]);
  if (fitting.size() == 1) {
    add_hint({MessageId::mis_two_mistakes, {}});
    add_hint({fitting[0].first->hint, {}});
    add_hint({fitting[0].second->hint, {}});
    return;
  }
  add_hint({MessageId::mis_weights_unexplained, {}});
}

GRADED_TEST(kStage, Stage09bMis, LightAndBsdfSamplesWeighted, 8) {
  // A floor under a quad light: every path's light sample, and its BSDF sample when that hits the
  // light, must count with their power-heuristic weights.
  expect_scripted({"a floor under a quad light", "四边形光源下的地面"}, quad_light_scene(), scripted_paths(2));
}

GRADED_TEST(kStage, Stage09bMis, PointLightKeepsWeightOne, 3) {
  // No direction hits a point: its light sample is the only way to find it, weight 1.
  expect_scripted({"a floor under a point light", "点光源下的地面"}, point_light_scene(), scripted_paths(2));
}

GRADED_TEST(kStage, Stage09bMis, LastVertexKeepsWeightOne, 2) {
  // max_depth 0: no BSDF sample follows the camera's hit, so its light sample has weight 1.
  expect_scripted({"a floor under a quad light, max depth 0", "四边形光源下的地面，最大深度 0"}, quad_light_scene(),
                  scripted_paths(0));
}

// ---- Unbiased: furnaces and Cornell boxes ---------------------------------------------------

void hint_biased() { add_hint({MessageId::mis_biased, {}}); }

void expect_furnace(int index) {
  const FurnaceRender render = render_furnace(index, test_seed(200 + static_cast<std::uint64_t>(index)), true);
  if (render.not_finite) {
    add_not_finite(render.not_finite, render.pixel_count());
    return;
  }
  const double exact = furnace_exact(kFurnaces[index]);
  const testkit::MeanTestResult result = furnace_exact_test(render.pixel_means, kFurnaces[index], exact, kLevel);
  const FurnaceSpreadResult spread = furnace_spread_test(render.pixel_means, kFurnaces[index], exact, kLevel);
  std::optional<ShortPathsResult> short_paths;
  if (kFurnaces[index].roulette < 1.0)
    short_paths = furnace_short_paths_test(
        render_furnace_paths(index, test_seed(220 + static_cast<std::uint64_t>(index)), true), kFurnaces[index], kLevel);
  if (result.passed && spread.passed && (!short_paths || short_paths->passed)) return;
  if (!result.passed) add_furnace_failure(index, result);
  if (!spread.passed) add_furnace_spread_failure(index, spread, exact, kLevel);
  if (short_paths && !short_paths->passed) add_furnace_short_paths_failure(index, *short_paths, kLevel);
  if (!result.passed || !spread.passed) {
    // The emission the camera sees directly lost (weighted as if a BSDF sample had found it): every
    // path is worth 1 less, which the same t-test tells.
    if (!result.passed && furnace_mean_test(render.pixel_means, exact - 1.0, kLevel).passed)
      add_hint({MessageId::mis_camera_hit_weighted, {}});
    else
      hint_biased();
  }
}

GRADED_TEST(kStage, Stage09bMis, FurnaceWithoutRoulette, 2) { expect_furnace(0); }
GRADED_TEST(kStage, Stage09bMis, FurnaceWithRoulette, 2) { expect_furnace(1); }

void expect_cornell(int scene_index) {
  const std::optional<RegionTest> test =
      expect_cornell_matches_reference(kStage, scene_index, true, test_seed(210 + static_cast<std::uint64_t>(scene_index)),
                                       kLevel, true);
  if (test && test->failures > 0) hint_biased();
}

GRADED_TEST(kStage, Stage09bMis, CornellBoxImageMatchesReference, 3) { expect_cornell(0); }
GRADED_TEST(kStage, Stage09bMis, SpecularCornellBoxImageMatchesReference, 3) { expect_cornell(1); }

}  // namespace
}  // namespace raylab::grading
