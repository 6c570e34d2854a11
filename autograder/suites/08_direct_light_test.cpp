// Autograder suite for stage 08_direct_light (30 points).
//
// The radiometry functions are judged against exact formulas (float tolerance), each wrong value
// checked against the mistakes that explain it. The one-sample estimator runs in the stage
// server, in test scenes the judge describes (08_direct_light_calls.h: direct_light_samples), and
// the judge t-tests the mean of its samples against the direct light in closed form: Lambert's
// formula for a polygon light, pi L (r / d)^2 cos for a sphere light above the horizon,
// I cos / d^2 for a point light, 0 behind an occluder.
//
// False failures: the estimator's mean tests (kMeanTests of them, one per query and channel)
// share kGraderFalseFailureRate (1 in 1,000 for the stage, Sidak-corrected); the exact checks
// have tolerances for float rounding that a correct implementation never exceeds. The mean tests
// count the samples' variance only up to kNoisierThanCorrectAllowed times a correct estimator's
// (variance_bound, by quadrature over each light): noise added to a biased estimate cannot hide
// the bias.
#include "08_direct_light_calls.h"
#include "direct_models.h"
#include "grading.h"
#include "support.h"

#include "raylab/error.h"
#include "raylab/math.h"
#include "raylab/random.h"
#include "raylab/stages/08_direct_light.h"
#include "raylab/testkit/statistics.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "08_direct_light";
constexpr double kPiD = 3.14159265358979323846;
constexpr std::uint32_t kSamplesPerQuery = 20000;
constexpr int kMeanTests = 15;  // 5 queries x 3 channels (EstimatorUnderQuadLight, EstimatorSeveralLights)
const double kLevel = testkit::sidak_level(testkit::kGraderFalseFailureRate, kMeanTests);

const bool kRegistered = register_stage(kStage, [] {
  // (A stub of stage 07 that the estimator samples with is stage 07's to report.)
  throw_if_every_function_is_a_stub(
      kStage, {[] { (void)point_light_intensity(glm::vec3(1.0f)); },
               [] { (void)point_light_irradiance(glm::vec3(1.0f), glm::vec3(0, 0, 1), glm::vec3(0.0f), glm::vec3(0, 0, 1)); },
               [] { (void)lambertian_f(glm::vec3(0.5f)); }, [] { (void)area_pdf_to_solid_angle(1.0f, 1.0f, 1.0f); },
               [] {
                 DirectLightScene scene;
                 scene.point_lights.push_back({glm::vec3(0, 0, 1), glm::vec3(1.0f)});
                 (void)direct_light_samples(scene, {DirectLightQuery{}}, 1);
               }});
});

std::string text(const glm::vec3& v) { return gtest_text(v); }
std::string text(float v) { return gtest_text(v); }

bool close(double got, double expected, double relative = 1e-5) {
  return std::fabs(got - expected) <= relative * std::fabs(expected) + 1e-30;
}
bool close(const glm::vec3& got, const glm::dvec3& expected, double relative = 1e-5) {
  return close(got.x, expected.x, relative) && close(got.y, expected.y, relative) && close(got.z, expected.z, relative);
}

void fail_value(const MessageArg& call, const std::string& got, const std::string& expected) {
  add_failure({MessageId::direct_failure_value, {call, {"got", got}, {"expected", expected}}});
}

// ---- Exact functions ---------------------------------------------------------------------

// Each check's exact answer (expected_...), for its comparison and its failure message alike.
glm::dvec3 expected_intensity(const glm::vec3& power) { return glm::dvec3(power) / (4.0 * kPiD); }

GRADED_TEST(kStage, Stage08DirectLight, PointLightIntensityFromPower, 3) {
  const glm::vec3 powers[] = {glm::vec3(4.0f * kPi), glm::vec3(100.0f, 50.0f, 10.0f), glm::vec3(1.0f, 0.0f, 2.5f)};
  for (const glm::vec3& power : powers) {
    const glm::vec3 got = point_light_intensity(power);
    const glm::dvec3 expected = expected_intensity(power);
    if (close(got, expected)) continue;
    fail_value({"call", "point_light_intensity(" + text(power) + ")"}, text(got), text(glm::vec3(expected)));
    if (hint_if_not_finite("point_light_intensity", {got.x, got.y, got.z}, {MessageId::direct_advice_division, {}})) return;
    if (close(static_cast<double>(got.x), expected.x) && got.x == got.y && got.y == got.z && power.x != power.y) {
      add_hint({MessageId::direct_intensity_not_per_channel, {}});
      return;
    }
    const double ratio = got.x / power.x;  // power.x > 0 in every case
    for (const double divisor : {1.0, kPiD, 2.0 * kPiD, 4.0, 2.0})
      if (close(ratio, 1.0 / divisor, 1e-4))
        add_hint({MessageId::direct_intensity_not_over_sphere, {{"divisor", divisor == 1.0 ? "1" : divisor == kPiD ? "pi" : divisor == 2.0 * kPiD ? "2 pi" : divisor == 4.0 ? "4" : "2"}}});
    return;
  }
}

struct IrradianceCase {
  glm::vec3 intensity, light, point, normal;
};
// The irradiance in double, with the distance and the cosine its hints compare against.
struct ExpectedIrradiance {
  double distance, cosine;
  glm::dvec3 irradiance;
};
ExpectedIrradiance expected_irradiance(const IrradianceCase& c) {
  const glm::dvec3 to_light = glm::dvec3(c.light) - glm::dvec3(c.point);
  const double d = glm::length(to_light);
  const double cosine = glm::dot(glm::dvec3(c.normal), to_light) / d;
  return {d, cosine, cosine > 0 ? glm::dvec3(c.intensity) * (cosine / (d * d)) : glm::dvec3(0.0)};
}

GRADED_TEST(kStage, Stage08DirectLight, PointLightIrradiance, 5) {
  const IrradianceCase cases[] = {
      {glm::vec3(10.0f), glm::vec3(0, 0, 2), glm::vec3(0.0f), glm::vec3(0, 0, 1)},                  // overhead
      {glm::vec3(3.0f, 2.0f, 1.0f), glm::vec3(3, 0, 4), glm::vec3(0.0f), glm::vec3(0, 0, 1)},        // cos 0.8, d 5
      {glm::vec3(7.0f), glm::vec3(1, 2, 3), glm::vec3(0.5f, -1, 0.25f), glm::normalize(glm::vec3(1, 1, 2))},
      {glm::vec3(5.0f), glm::vec3(0, 0, -2), glm::vec3(0.0f), glm::vec3(0, 0, 1)},                 // behind
  };
  for (const IrradianceCase& c : cases) {
    const glm::vec3 got = point_light_irradiance(c.intensity, c.light, c.point, c.normal);
    const ExpectedIrradiance expected = expected_irradiance(c);
    const double d = expected.distance, cosine = expected.cosine;
    if (close(got, expected.irradiance, 2e-5)) continue;
    const Message call{MessageId::direct_call_irradiance,
                       {{"intensity", text(c.intensity)}, {"light", text(c.light)}, {"point", text(c.point)},
                        {"normal", text(c.normal)}}};
    fail_value({"call", call}, text(got), text(glm::vec3(expected.irradiance)));
    if (hint_if_not_finite("point_light_irradiance", {got.x, got.y, got.z}, {MessageId::direct_advice_division, {}})) return;
    const glm::dvec3 intensity(c.intensity);
    if (cosine <= 0) add_hint({MessageId::direct_irradiance_behind, {}});
    else if (close(got, intensity / (d * d), 1e-4)) add_hint({MessageId::direct_irradiance_no_cosine, {}});
    else if (close(got, intensity * (cosine / d), 1e-4)) add_hint({MessageId::direct_irradiance_not_squared, {}});
    return;
  }
}

const glm::vec3 kAlbedos[] = {glm::vec3(1.0f), glm::vec3(0.725f, 0.71f, 0.68f), glm::vec3(0.0f, 0.5f, 0.25f)};
glm::dvec3 expected_lambertian_f(const glm::vec3& albedo) { return glm::dvec3(albedo) / kPiD; }
bool lambertian_f_right(const glm::vec3& albedo, const glm::vec3& got) { return close(got, expected_lambertian_f(albedo)); }

GRADED_TEST(kStage, Stage08DirectLight, LambertianF, 4) {
  for (const glm::vec3& albedo : kAlbedos) {
    const glm::vec3 got = lambertian_f(albedo);
    if (lambertian_f_right(albedo, got)) continue;
    fail_value({"call", "lambertian_f(" + text(albedo) + ")"}, text(got), text(glm::vec3(expected_lambertian_f(albedo))));
    if (hint_if_not_finite("lambertian_f", {got.x, got.y, got.z}, {MessageId::direct_advice_division, {}})) return;
    if (close(got, glm::dvec3(albedo), 1e-4)) add_hint({MessageId::direct_lambertian_no_pi, {}});
    else if (close(got, glm::dvec3(albedo) / (2.0 * kPiD), 1e-4)) add_hint({MessageId::direct_lambertian_two_pi, {}});
    return;
  }
}

struct AreaPdfCase {
  float pdf_area, distance, cos_at_light;
};
const AreaPdfCase kAreaPdfCases[] = {
    {0.5f, 2.0f, 1.0f}, {0.01f, 3.0f, 0.6f}, {2.0f, 0.5f, 0.25f}, {1.0f / 13650.0f, 400.0f, 0.8f}};
double expected_area_pdf(const AreaPdfCase& c) {
  const double pdf = c.pdf_area, d = c.distance, cosine = c.cos_at_light;
  return pdf * d * d / cosine;
}
bool area_pdf_right(const AreaPdfCase& c, float got) { return close(got, expected_area_pdf(c), 2e-5); }

GRADED_TEST(kStage, Stage08DirectLight, AreaPdfToSolidAngle, 5) {
  for (const AreaPdfCase& c : kAreaPdfCases) {
    const float got = area_pdf_to_solid_angle(c.pdf_area, c.distance, c.cos_at_light);
    if (area_pdf_right(c, got)) continue;
    const std::string call = "area_pdf_to_solid_angle(pdf_area " + text(c.pdf_area) + ", distance " + text(c.distance) +
                             ", cos_at_light " + text(c.cos_at_light) + ")";
    fail_value({"call", call}, text(got), gtest_text(static_cast<float>(expected_area_pdf(c))));
    const double pdf = c.pdf_area, d = c.distance, cosine = c.cos_at_light;
    if (hint_if_not_finite("area_pdf_to_solid_angle", {got}, {MessageId::direct_advice_division, {}})) return;
    if (close(got, pdf, 1e-4)) add_hint({MessageId::direct_pdf_not_converted, {}});
    else if (close(got, pdf * d * d, 1e-4)) add_hint({MessageId::direct_pdf_no_cosine, {}});
    else if (close(got, pdf * d / cosine, 1e-4)) add_hint({MessageId::direct_pdf_not_squared, {}});
    else if (close(got, pdf * cosine / (d * d), 1e-4)) add_hint({MessageId::direct_pdf_inverted, {}});
    return;
  }
}

// ---- The estimator -------------------------------------------------------------------------

// Irradiance at x (unit normal n) from a polygon of radiance 1 seen from its front, wholly above
// x's horizon: Lambert's formula, E = 1/2 sum_i angle(v_i, v_i+1) (n . unit(v_i x v_i+1)).
double polygon_irradiance(const std::vector<glm::dvec3>& corners, const glm::dvec3& x, const glm::dvec3& n) {
  double sum = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const glm::dvec3 a = glm::normalize(corners[i] - x), b = glm::normalize(corners[(i + 1) % corners.size()] - x);
    const double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
    sum += angle * glm::dot(n, glm::normalize(glm::cross(a, b)));
  }
  return 0.5 * std::fabs(sum);
}

// A quad light facing down (-y) at height y, x in [x0, x1], z in [z0, z1], as two triangles.
void add_quad_light(DirectLightScene& scene, float x0, float x1, float z0, float z1, float y, const glm::vec3& radiance) {
  const glm::vec3 a(x1, y, z0), b(x1, y, z1), c(x0, y, z1), d(x0, y, z0);
  scene.triangles.push_back({a, b, c, radiance});  // wound so that its normal points down
  scene.triangles.push_back({a, c, d, radiance});
}

// This stage's verdict on lambertian_f or area_pdf_to_solid_angle: the values its own tests check;
// false for a stub.
bool direct_light_function_passes(const std::string& function) {
  try {
    if (function == "lambertian_f") {
      for (const glm::vec3& albedo : kAlbedos)
        if (!lambertian_f_right(albedo, lambertian_f(albedo))) return false;
    } else if (function == "area_pdf_to_solid_angle") {
      for (const AreaPdfCase& c : kAreaPdfCases)
        if (!area_pdf_right(c, area_pdf_to_solid_angle(c.pdf_area, c.distance, c.cos_at_light))) return false;
    }
  } catch (const NotImplemented&) {
    return false;
  }
  return true;
}

// The stage's own functions that estimate_direct_light runs through the framework: bsdf_f calls
// lambertian_f, and sample_li, for an area light, area_pdf_to_solid_angle.
struct Helper {
  const char* function;  // as direct_light_function_passes names it
  const char* test;      // its own test
  const char* caller;    // the framework's function that calls it
};
const Helper kLambertianFHelper{"lambertian_f", "LambertianF", "bsdf_f"};
const Helper kAreaPdfHelper{"area_pdf_to_solid_angle", "AreaPdfToSolidAngle", "sample_li"};

// Inside a failing estimator test: for each of `helpers` that fails its own test, the hint
// direct_helper_fails ("your area_pdf_to_solid_angle fails its own test ...: fix it first"); true
// when any does, so that the caller adds no hint about the estimator itself.
bool hint_failing_helpers(const std::vector<Helper>& helpers) {
  bool any = false;
  for (const Helper& helper : helpers) {
    if (direct_light_function_passes(helper.function)) continue;
    add_hint({MessageId::direct_helper_fails,
              {{"function", helper.function}, {"test", helper.test}, {"caller", helper.caller}}});
    any = true;
  }
  return any;
}

// The modelled mistakes (direct_models.h) that explain a mean: the first single mistake that fits,
// else the one pair that does (none when two pairs fit alike); a factor fits within 4 standard
// errors. The choice's mistake needs more than one light.
std::vector<const DirectMistake*> fit_direct_mistakes(const testkit::MeanTestResult& result, int light_count) {
  const auto fits = [&](double factor) {
    return std::fabs(result.mean - factor * result.expected_mean) <= 4.0 * result.standard_error + 1e-9;
  };
  std::vector<const DirectMistake*> candidates;
  for (const DirectMistake& mistake : direct_mistakes())
    if (light_count > 1 || mistake.hint != MessageId::direct_estimate_no_choice_probability) candidates.push_back(&mistake);
  for (const DirectMistake* mistake : candidates)
    if (fits(mistake->factor(light_count))) return {mistake};
  std::vector<const DirectMistake*> pair;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    for (std::size_t j = i + 1; j < candidates.size(); ++j)
      if (fits(candidates[i]->factor(light_count) * candidates[j]->factor(light_count))) {
        if (!pair.empty()) return {};
        pair = {candidates[i], candidates[j]};
      }
  return pair;
}

struct Expectation {
  Message what;  // the case, in words (direct_case_...)
  DirectLightQuery query;
  glm::dvec3 radiance;  // the exact expected value of the estimate
};

// ---- The spread a correct estimator can have -----------------------------------------------

// How many times the variance of a correct estimator the mean tests count of yours (as stage 09's
// kNoisierThanReferenceAllowed): noise added to a biased estimate cannot widen the test past it.
constexpr double kNoisierThanCorrectAllowed = 4.0;

// One light as the variance bound sees it: the mean of the square of its sample's value (f L cos /
// pdf, before dividing by the chance of choosing the light) over the points sample_li draws on it,
// per channel, and its power (the sum of the channels), for a choice by power.
struct LightMoments {
  glm::dvec3 mean_square{0.0};
  double power = 0;
};

// A sample of an area light at `y` (normal `light_normal`, `area` the area sample_li samples with
// uniform density), seen from the query's point: f L cos_x cos_y area / d^2, or 0 when either
// side faces away (an unoccluded test scene: nothing else makes it 0).
glm::dvec3 area_sample_value(const DirectLightQuery& query, const glm::dvec3& emission, const glm::dvec3& y,
                             const glm::dvec3& light_normal, double area) {
  const glm::dvec3 x(query.point), to_light = y - x;
  const double d2 = glm::dot(to_light, to_light);
  const glm::dvec3 wi = to_light / std::sqrt(d2);
  const double cos_x = glm::dot(glm::dvec3(query.normal), wi), cos_y = -glm::dot(light_normal, wi);
  if (!(cos_x > 0.0 && cos_y > 0.0)) return glm::dvec3(0.0);
  return glm::dvec3(query.albedo) / kPiD * emission * (cos_x * cos_y * area / d2);
}

// The moments of each light of `scene` at `query`, by a midpoint rule on a grid of the unit square
// that sample_li's warps map to the light (uniform by area on a triangle, on the whole sphere).
std::vector<LightMoments> light_moments(const DirectLightScene& scene, const DirectLightQuery& query) {
  constexpr int kGrid = 256;
  std::vector<LightMoments> lights;
  const auto over_grid = [&](auto point_and_normal, const glm::dvec3& emission, double area) {
    LightMoments light;
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        const auto [y, normal] = point_and_normal((i + 0.5) / kGrid, (j + 0.5) / kGrid);
        const glm::dvec3 value = area_sample_value(query, emission, y, normal, area);
        light.mean_square += value * value / double(kGrid * kGrid);
      }
    light.power = kPiD * area * (emission.x + emission.y + emission.z);
    return light;
  };
  for (const DirectLightTriangle& t : scene.triangles) {
    const glm::dvec3 p0(t.p0), p1(t.p1), p2(t.p2), emission(t.emission);
    if (emission == glm::dvec3(0.0)) continue;  // an occluder, not a light
    const glm::dvec3 cross = glm::cross(p1 - p0, p2 - p0);
    const double area = 0.5 * glm::length(cross);
    const glm::dvec3 normal = glm::normalize(cross);
    lights.push_back(over_grid(
        [&](double u, double v) {
          const double root = std::sqrt(u);  // uniform by area: barycentrics (1 - sqrt u, v sqrt u)
          return std::make_pair(p0 * (1.0 - root) + p1 * (root * (1.0 - v)) + p2 * (root * v), normal);
        },
        emission, area));
  }
  for (const DirectLightSphere& sphere : scene.spheres) {
    const glm::dvec3 center(sphere.center);
    const double r = sphere.radius;
    lights.push_back(over_grid(
        [&](double u, double v) {
          const double z = 1.0 - 2.0 * u, ring = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPiD * v;
          const glm::dvec3 normal(ring * std::cos(phi), ring * std::sin(phi), z);
          return std::make_pair(center + r * normal, normal);
        },
        glm::dvec3(sphere.emission), 4.0 * kPiD * r * r));
  }
  for (const DirectLightPoint& light : scene.point_lights) {
    const glm::dvec3 to_light = glm::dvec3(light.position) - glm::dvec3(query.point);
    const double d2 = glm::dot(to_light, to_light);
    const double cos_x = std::max(0.0, glm::dot(glm::dvec3(query.normal), to_light / std::sqrt(d2)));
    const glm::dvec3 value = glm::dvec3(query.albedo) / kPiD * glm::dvec3(light.intensity) * (cos_x / d2);
    const glm::dvec3 intensity(light.intensity);
    lights.push_back({value * value, 4.0 * kPiD * (intensity.x + intensity.y + intensity.z)});
  }
  return lights;
}

// The most variance per channel that the mean tests count of an estimator at `query` whose mean is
// `mean`: kNoisierThanCorrectAllowed times a correct estimator's, one light chosen uniformly (the
// contract's LightSet::choose) or by power, whichever varies more. (Any estimator of the contract
// that varies more is rarer than the tests' false failures: one that sums over the lights varies
// less.) E[X^2] = sum over the lights of E[value^2] / chance of choosing it.
glm::dvec3 variance_bound(const DirectLightScene& scene, const DirectLightQuery& query, const glm::dvec3& mean) {
  const std::vector<LightMoments> lights = light_moments(scene, query);
  double total_power = 0;
  for (const LightMoments& light : lights) total_power += light.power;
  glm::dvec3 uniform(0.0), by_power(0.0);
  for (const LightMoments& light : lights) {
    uniform += light.mean_square * double(lights.size());
    if (light.power > 0) by_power += light.mean_square * (total_power / light.power);
  }
  const glm::dvec3 second_moment = glm::max(uniform, by_power);
  return kNoisierThanCorrectAllowed * glm::max(second_moment - mean * mean, glm::dvec3(0.0));
}

// Runs the queries, t-tests each channel's mean; names the first failure and the mistakes that fit,
// unless one of `helpers` (this stage's functions that the estimator runs) fails its own tests:
// then it names those instead. (Stage 07's warps, which sample the lights, are the grader's own
// here: stages.json, "grader_versions".)
void expect_means(const DirectLightScene& scene, const std::vector<Expectation>& expectations, int light_count,
                  const std::vector<Helper>& helpers) {
  std::vector<DirectLightQuery> queries;
  for (const Expectation& e : expectations) queries.push_back(e.query);
  const std::vector<glm::vec3> samples = direct_light_samples(scene, queries, test_seed(8));
  std::size_t offset = 0;
  bool failed = false;
  for (const Expectation& e : expectations) {
    testkit::RunningMoments moments[3];
    for (std::uint32_t i = 0; i < e.query.sample_count; ++i)
      for (int c = 0; c < 3; ++c) moments[c].add(samples[offset + i][c]);
    for (std::uint32_t i = 0; i < e.query.sample_count; ++i) {
      const glm::vec3& s = samples[offset + i];
      if (hint_if_not_finite(Message{MessageId::direct_case_estimate, {{"what", e.what}}}, {s.x, s.y, s.z},
                             {MessageId::direct_advice_division, {}}))
        return add_failure({MessageId::direct_failure_not_finite, {{"what", e.what}}});
    }
    offset += e.query.sample_count;
    const glm::dvec3 max_variance = variance_bound(scene, e.query, e.radiance);
    for (int c = 0; c < 3; ++c) {
      const testkit::MeanTestResult result = testkit::mean_test(moments[c], e.radiance[c], kLevel, 0.0, max_variance[c]);
      if (result.passed || failed) continue;
      failed = true;
      const double noise_ratio = moments[c].variance() / (max_variance[c] / kNoisierThanCorrectAllowed);
      if (noise_ratio > kNoisierThanCorrectAllowed)
        add_hint({MessageId::direct_too_noisy,
                  {{"ratio", gtest_text(noise_ratio)}, {"limit", gtest_text(kNoisierThanCorrectAllowed)}}});
      add_failure({MessageId::direct_failure_mean,
                   {{"what", e.what},
                    {"count", std::to_string(result.count)},
                    {"channel", std::to_string(c)},
                    {"mean", gtest_text(result.mean)},
                    {"error", gtest_text(result.standard_error)},
                    {"expected", gtest_text(result.expected_mean)},
                    {"p_value", gtest_text(result.p_value)},
                    {"level", gtest_text(result.significance_level)}}});
      const bool helper_fails = hint_failing_helpers(helpers);
      // Which modelled mistakes explain the mean (direct_models.h)? Judged against the noise: within
      // 4 standard errors.
      const std::vector<const DirectMistake*> fitted = fit_direct_mistakes(result, light_count);
      auto add_fitted_hints = [&](bool skip_bsdf) {
        if (fitted.size() == 2) add_hint({MessageId::direct_two_mistakes, {}});
        for (const DirectMistake* mistake : fitted)
          if (!(skip_bsdf && mistake->in_bsdf)) add_hint({mistake->hint, {{"lights", std::to_string(light_count)}}});
      };
      if (helper_fails) {
        // Its own test names the helper's mistake; a mistake of the estimator's own made with it is
        // named too when the two together explain the mean (lambertian_f without 1 / pi is the
        // bsdf factor).
        const bool bsdf_helper_fails = !direct_light_function_passes(kLambertianFHelper.function);
        if (bsdf_helper_fails && fitted.size() == 2) add_fitted_hints(true);
        continue;
      }
      // No occluder in these scenes: a correct estimator's black samples are those of a sphere
      // light's far side (an eighth of the samples with four lights); the shadow ray that hits the
      // light itself makes every area light's sample black (half of them with four lights, two of
      // them point lights).
      std::uint32_t black = 0;
      for (std::size_t i = offset - e.query.sample_count; i < offset; ++i) black += samples[i] == glm::vec3(0.0f);
      if (3 * black > e.query.sample_count)
        add_hint({MessageId::direct_estimate_zero_light_hit, {{"black", std::to_string(black)},
                                                              {"total", std::to_string(e.query.sample_count)}}});
      else if (!fitted.empty())
        add_fitted_hints(false);
      else
        add_hint({MessageId::direct_estimate_ratio, {{"ratio", gtest_text(result.mean / result.expected_mean)}}});
    }
  }
}

GRADED_TEST(kStage, Stage08DirectLight, EstimatorUnderQuadLight, 5) {
  // GAMES101's ceiling light, radiance 10, and points under it: on the floor below, off to the
  // side, and on a tilted surface.
  DirectLightScene scene;
  add_quad_light(scene, 213, 343, 227, 332, 548.7f, glm::vec3(10.0f, 8.0f, 6.0f));
  const std::vector<glm::dvec3> corners = {{213, 548.7, 227}, {213, 548.7, 332}, {343, 548.7, 332}, {343, 548.7, 227}};
  std::vector<Expectation> expectations;
  auto add = [&](MessageId what, glm::vec3 point, glm::vec3 normal, glm::vec3 albedo) {
    normal = glm::normalize(normal);
    const double e = polygon_irradiance(corners, glm::dvec3(point), glm::dvec3(normal));
    const glm::dvec3 radiance = glm::dvec3(albedo) / kPiD * glm::dvec3(10.0, 8.0, 6.0) * e;
    expectations.push_back({what, DirectLightQuery{point, normal, normal, albedo, kSamplesPerQuery}, radiance});
  };
  add(MessageId::direct_case_floor_under_light, glm::vec3(278, 0, 280), glm::vec3(0, 1, 0), glm::vec3(0.725f, 0.71f, 0.68f));
  add(MessageId::direct_case_floor_near_wall, glm::vec3(40, 0, 500), glm::vec3(0, 1, 0), glm::vec3(0.5f));
  add(MessageId::direct_case_tilted_surface, glm::vec3(300, 200, 100), glm::vec3(0.3f, 1.0f, 0.5f), glm::vec3(0.63f, 0.065f, 0.05f));
  expect_means(scene, expectations, 2, {kLambertianFHelper, kAreaPdfHelper});
  // The same samples asked twice with the same seed: the same estimates (no rand()).
  DirectLightQuery query = expectations[0].query;
  query.sample_count = 256;
  const std::vector<glm::vec3> first = direct_light_samples(scene, {query}, test_seed(81));
  const std::vector<glm::vec3> second = direct_light_samples(scene, {query}, test_seed(81));
  const std::size_t differing = bitwise_differences(first, second);
  if (differing > 0)
    add_failure({MessageId::direct_failure_not_repeatable,
                 {{"what", expectations[0].what},
                  {"count", std::to_string(differing)},
                  {"total", std::to_string(first.size())}}});
}

GRADED_TEST(kStage, Stage08DirectLight, EstimatorSeveralLights, 4) {
  // A triangle light, a sphere light and two point lights together; the estimator picks one per
  // sample, so it must divide by the chance of the one it picked. Four lights, not three: with
  // three, the choice not divided by and 1 / pi missing together give pi / 3, within 5% of the
  // right answer (direct_models.h).
  DirectLightScene scene;
  const glm::vec3 t0(-1, 3, -1), t1(1, 3, 0), t2(-1, 3, 1);  // faces down (by its winding)
  scene.triangles.push_back({t0, t1, t2, glm::vec3(4.0f)});
  scene.spheres.push_back({glm::vec3(3, 2, 0), 0.5f, glm::vec3(2.0f, 3.0f, 1.0f)});
  const glm::dvec3 point_lights[2][2] = {{{-2, 2, 1}, {5.0, 1.0, 2.0}}, {{1, 2.5, -2}, {1.0, 4.0, 2.0}}};
  for (const auto& light : point_lights) scene.point_lights.push_back({glm::vec3(light[0]), glm::vec3(light[1])});
  std::vector<Expectation> expectations;
  auto add = [&](MessageId what, glm::vec3 point, glm::vec3 normal, glm::vec3 albedo) {
    normal = glm::normalize(normal);
    const glm::dvec3 x(point), n(normal);
    glm::dvec3 e = glm::dvec3(4.0) * polygon_irradiance({glm::dvec3(t0), glm::dvec3(t1), glm::dvec3(t2)}, x, n);
    const glm::dvec3 to_sphere = glm::dvec3(3, 2, 0) - x;
    const double d = glm::length(to_sphere);
    e += glm::dvec3(2.0, 3.0, 1.0) * (kPiD * (0.25 / (d * d)) * glm::dot(n, to_sphere / d));
    for (const auto& light : point_lights) {
      const glm::dvec3 to_point = light[0] - x;
      const double dp = glm::length(to_point);
      e += light[1] * (glm::dot(n, to_point / dp) / (dp * dp));
    }
    expectations.push_back({what, DirectLightQuery{point, normal, normal, albedo, kSamplesPerQuery},
                            glm::dvec3(albedo) / kPiD * e});
  };
  add(MessageId::direct_case_point_four_lights, glm::vec3(0, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0.8f));
  add(MessageId::direct_case_tilted_point_four_lights, glm::vec3(0.5f, 0.2f, 0.3f), glm::vec3(0.2f, 1.0f, -0.1f),
      glm::vec3(0.3f, 0.6f, 0.9f));
  expect_means(scene, expectations, 4, {kLambertianFHelper, kAreaPdfHelper});
}

GRADED_TEST(kStage, Stage08DirectLight, ShadowRaysAndBackFaces, 3) {
  // Every sample must be exactly black: a light hidden behind an occluder, and a surface that the
  // light shines on from behind (the surface faces away from it). And none black on a surface of
  // the scene that sees the whole light.
  DirectLightScene scene;
  add_quad_light(scene, -1, 1, -1, 1, 4.0f, glm::vec3(10.0f));
  // A black occluder, larger than the light, between it and the point at the origin.
  scene.triangles.push_back({glm::vec3(-3, 2, -3), glm::vec3(-3, 2, 3), glm::vec3(3, 2, 3), glm::vec3(0.0f)});
  scene.triangles.push_back({glm::vec3(-3, 2, -3), glm::vec3(3, 2, 3), glm::vec3(3, 2, -3), glm::vec3(0.0f)});
  const DirectLightQuery hidden{glm::vec3(0, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0), glm::vec3(0.8f), 2000};
  // Between the occluder and the light, facing down, away from the light, which shines on it.
  const DirectLightQuery facing_away{glm::vec3(0, 3, 0), glm::vec3(0, -1, 0), glm::vec3(0, -1, 0), glm::vec3(0.8f), 2000};
  const std::vector<glm::vec3> samples = direct_light_samples(scene, {hidden, facing_away}, test_seed(9));
  std::size_t lit_hidden = 0, lit_behind = 0;
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (samples[i] != glm::vec3(0.0f)) ++(i < hidden.sample_count ? lit_hidden : lit_behind);
  if (lit_hidden > 0) {
    add_failure({MessageId::direct_failure_lit_hidden, {{"count", std::to_string(lit_hidden)}, {"total", "2000"}}});
    add_hint({MessageId::direct_estimate_no_shadow, {}});
  }
  if (lit_behind > 0) {
    add_failure({MessageId::direct_failure_lit_behind, {{"count", std::to_string(lit_behind)}, {"total", "2000"}}});
    add_hint({MessageId::direct_estimate_from_behind, {}});
  }
  // Points on a surface of the scene: a tilted black floor under the light, which every point sees
  // whole, so that no sample may be black. Each point is the floor's, rounded to float as a hit
  // point is: some lie just behind the floor, and a shadow ray from the point itself, not from
  // offset_ray_origin, finds the floor again at a tiny t (shadow acne).
  DirectLightScene light_only;
  add_quad_light(light_only, -1, 1, -1, 1, 4.0f, glm::vec3(10.0f));
  DirectLightScene floor_scene = light_only;
  const glm::vec3 f0(-3.1f, 0.37f, -2.9f), f1(-2.7f, -0.29f, 3.3f), f2(3.2f, 0.23f, 2.8f), f3(2.9f, 0.61f, -3.2f);
  floor_scene.triangles.push_back({f0, f1, f2, glm::vec3(0.0f)});
  floor_scene.triangles.push_back({f0, f2, f3, glm::vec3(0.0f)});
  std::vector<DirectLightQuery> on_floor;
  Pcg32 random(test_seed(13), testkit::stream_of("08_direct_light/on the floor"));
  for (int i = 0; i < 64; ++i) {
    const bool first = i % 2 == 0;
    const glm::vec3 a = f0, b = first ? f1 : f2, c = first ? f2 : f3;
    // Barycentrics near the middle of the floor, where the whole light is above the tangent plane.
    const float b1 = 0.25f + 0.2f * random.next_float(), b2 = 0.25f + 0.2f * random.next_float();
    const glm::vec3 point = (1.0f - b1 - b2) * a + b1 * b + b2 * c;
    const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
    on_floor.push_back({point, normal, normal, glm::vec3(0.8f), 16});
  }
  // The same points with the floor taken away (light_only): black there is another mistake (the
  // shadow ray hitting the light itself), which the estimator tests charge.
  const auto black_count = [](const std::vector<glm::vec3>& estimates) {
    std::size_t black = 0;
    for (const glm::vec3& estimate : estimates) black += estimate == glm::vec3(0.0f);
    return black;
  };
  const std::vector<glm::vec3> floor_samples = direct_light_samples(floor_scene, on_floor, test_seed(12));
  const std::size_t black_on_floor = black_count(floor_samples);
  if (black_on_floor > 0 && black_count(direct_light_samples(light_only, on_floor, test_seed(12))) == 0) {
    add_failure({MessageId::direct_failure_black_on_surface,
                 {{"count", std::to_string(black_on_floor)}, {"total", std::to_string(floor_samples.size())}}});
    add_hint({MessageId::direct_estimate_shadow_acne, {}});
  }
  // A scene with no light at all (one black triangle): nothing to choose, every sample black.
  DirectLightScene dark;
  dark.triangles.push_back({glm::vec3(-3, 2, -3), glm::vec3(-3, 2, 3), glm::vec3(3, 2, 3), glm::vec3(0.0f)});
  const DirectLightQuery unlit{glm::vec3(0, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0), glm::vec3(0.8f), 100};
  std::vector<glm::vec3> dark_samples;
  {
    const HintIfLost hint(MessageId::direct_estimate_no_lights);  // (choosing from no light may crash)
    dark_samples = direct_light_samples(dark, {unlit}, test_seed(11));
  }
  std::size_t lit_dark = 0;
  for (const glm::vec3& sample : dark_samples) lit_dark += sample != glm::vec3(0.0f);
  if (lit_dark > 0) {
    add_failure({MessageId::direct_failure_lit_without_lights, {{"count", std::to_string(lit_dark)}, {"total", "100"}}});
    add_hint({MessageId::direct_estimate_no_lights, {}});
  }
}

GRADED_TEST(kStage, Stage08DirectLight, EstimatorPointLightExact, 1) {
  // One point light: no randomness left, every sample is f I cos / d^2.
  DirectLightScene scene;
  scene.point_lights.push_back({glm::vec3(1, 3, 2), glm::vec3(6.0f, 3.0f, 1.5f)});
  const glm::vec3 normal = glm::normalize(glm::vec3(0.1f, 1.0f, 0.2f));
  const DirectLightQuery query{glm::vec3(0.0f), normal, normal, glm::vec3(0.5f, 0.6f, 0.7f), 16};
  const std::vector<glm::vec3> samples = direct_light_samples(scene, {query}, test_seed(10));
  const glm::dvec3 to_light(1, 3, 2);
  const double d = glm::length(to_light);
  const glm::dvec3 expected = glm::dvec3(0.5, 0.6, 0.7) / kPiD * glm::dvec3(6.0, 3.0, 1.5) *
                              (glm::dot(glm::dvec3(normal), to_light / d) / (d * d));
  for (const glm::vec3& s : samples)
    if (!close(s, expected, 1e-4)) {
      fail_value({"call", Message(MessageId::direct_call_one_point_light)}, text(s),
                 text(glm::vec3(expected)));
      hint_failing_helpers({kLambertianFHelper});  // (a point light's sample has no area pdf)
      return;
    }
}

}  // namespace

}  // namespace raylab::grading
