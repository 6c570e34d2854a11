// Autograder suite for stage 10_microfacet (bonus, 30 points).
//
// The values (D, G1, f and both densities) are judged against the exact formulas in double
// precision (float tolerances). A wrong function is diagnosed from a fitted model of what it
// computed: a small family of formulas, each a product of parts (which distribution, which
// alpha, whether 1 / pi, the masking, the Fresnel cosine, the factor 4, the Jacobian), and the
// judge looks for the member that reproduces EVERY value the student returned above the surface,
// fewest changed parts first (microfacet_models.h; 0 below the surface is a rule with its own
// hint). Each changed part is a hint of its own, so two mistakes at once get two hints, after a
// line that says they were made together; a part that is the student's own wrong function (f
// built on a wrong D) names that function, not f.
//
// The samplers run in bulk in the stage server (10_microfacet_calls.h). The judge maps every
// half vector (for sample_microfacet_wi: h = normalize(wo + wi)) to the coordinates in which
// GGX's density D(h) cos(theta_h) is uniform, (tan^2 / (alpha^2 + tan^2), phi / 2 pi), and
// chi-square tests them on a 16 x 16 grid. A sampler that fails is held against the densities of
// the known mistakes and pairs of them (a shape with an alpha) the same way; the first that fits
// (p above 1e-6) names its hints.
//
// False failures: the 4 chi-square tests share kGraderFalseFailureRate (1 in 1,000 for the stage,
// Sidak-corrected); the value tests are exact checks with tolerances for float rounding, which a
// correct implementation never fails.
#include "10_microfacet_calls.h"
#include "grading.h"
#include "microfacet_models.h"
#include "support.h"

#include "raylab/error.h"
#include "raylab/random.h"
#include "raylab/stages/10_microfacet.h"
#include "raylab/testkit/statistics.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace raylab::grading {
namespace {

using namespace microfacet;  // the formulas and the models (microfacet_models.h)

constexpr const char* kStage = "10_microfacet";
constexpr int kSampleCount = 100000;
constexpr std::uint64_t kSeed = kStageSeed;
const double kLevel = testkit::sidak_level(testkit::kGraderFalseFailureRate, 4);

const bool kRegistered = register_stage(kStage, [] {
  const glm::vec3 n(0, 0, 1);
  throw_if_every_function_is_a_stub(
      kStage, {[&] { (void)ggx_distribution(n, 0.5f); }, [&] { (void)ggx_smith_g1(n, 0.5f); },
               [&] { (void)microfacet_f(n, n, 0.5f, glm::vec3(1.0f)); },
               [&] { (void)ggx_half_vector_samples(0.5f, {glm::vec2(0.5f)}); },
               [&] { (void)ggx_half_vector_pdf(n, 0.5f); },
               [&] { (void)microfacet_wi_samples(n, 0.5f, {glm::vec2(0.5f)}); },
               [&] { (void)microfacet_pdf(n, n, 0.5f); }});
});

MessageArg section(int number) {
  const std::string n = std::to_string(number);
  return MessageArg::bilingual("section", "docs/10_microfacet.md, section " + n, "docs/zh/10_microfacet.md，第 " + n + " 节");
}

std::string text(const glm::vec3& v) { return gtest_text(v); }
std::string text(float v) { return gtest_text(v); }

// A hint for each changed part of the fitted model, or a note that none fits.
void hint_alpha(AlphaUse use, int section_number) {
  if (use == AlphaUse::SquaredFirst) add_hint({MessageId::microfacet_alpha_squared_first, {section(section_number)}});
  if (use == AlphaUse::SquareRoot) add_hint({MessageId::microfacet_alpha_not_squared, {section(section_number)}});
}

void fail_value(const std::string& call, const std::string& got, const std::string& expected) {
  add_failure({MessageId::microfacet_failure_value, {{"call", call}, {"got", got}, {"expected", expected}}});
}

// "ggx_distribution((0, 0, 1), 0.25)": a call as C++ writes it, the same in both languages.
std::string call_text(const char* function, std::initializer_list<std::string> arguments) {
  std::string joined;
  for (const std::string& a : arguments) joined += (joined.empty() ? "" : ", ") + a;
  return std::string(function) + "(" + joined + ")";
}

// ---- D -------------------------------------------------------------------------------------

// The hint for values below the surface that are not 0: the only mistake, or one more. Returns
// whether the diagnosis goes on, to the values above.
bool hint_below_and_go_on(const char* function, bool above_right, bool below_right, int section_number) {
  if (!below_right)
    add_hint({above_right ? MessageId::microfacet_below_not_zero : MessageId::microfacet_also_below_not_zero,
              {{"function", function}, section(section_number)}});
  return !above_right;
}

// Fails with the first case whose value is not exact(case), and hints when a value below the
// surface is not 0. Returns whether the diagnosis should go on, to the values above the surface:
// false when every value is right, when a value is not finite, or when those above are all right.
template <typename Exact>
bool fail_first_wrong(const char* function, const std::vector<ValueCase>& cases, const Exact& exact, int section_number) {
  const auto wrong = std::find_if(cases.begin(), cases.end(), [&](const ValueCase& k) { return !close(k.got, exact(k)); });
  if (wrong == cases.end()) return false;
  fail_value(call_text(function, {text(wrong->vector), text(wrong->alpha)}), text(wrong->got),
             text(static_cast<float>(exact(*wrong))));
  if (hint_if_not_finite(function, {wrong->got}, {MessageId::microfacet_advice_division, {section(section_number)}}))
    return false;
  const auto right_where = [&](bool above) {
    return std::all_of(cases.begin(), cases.end(),
                       [&](const ValueCase& k) { return (k.vector.z > 0.0f) != above || close(k.got, exact(k)); });
  };
  return hint_below_and_go_on(function, right_where(true), right_where(false), section_number);
}

// The line before the hints of a fitted model with more than one changed part.
void hint_together(int changes) {
  if (changes > 1) add_hint({MessageId::microfacet_mistakes_together, {{"count", std::to_string(changes)}}});
}

double exact_distribution(const ValueCase& k) { return ggx_d(k.vector.z, k.alpha); }
double exact_smith_g1(const ValueCase& k) { return smith_g1(k.vector.z, k.alpha); }
double exact_half_vector_pdf(const ValueCase& k) { return ggx_d(k.vector.z, k.alpha) * std::max(0.0f, k.vector.z); }

template <typename Exact>
bool all_close(const std::vector<ValueCase>& cases, const Exact& exact) {
  return std::all_of(cases.begin(), cases.end(), [&](const ValueCase& k) { return close(k.got, exact(k)); });
}

// Whether the student's D and G1 are right (asked once; other tests' hints name them).
bool distribution_is_right() {
  static const bool right = all_close(value_cases(0.7f, ggx_distribution), exact_distribution);
  return right;
}
bool smith_g1_is_right() {
  static const bool right = all_close(value_cases(2.1f, ggx_smith_g1), exact_smith_g1);
  return right;
}

GRADED_TEST(kStage, Stage10Microfacet, GgxDistribution, 5) {
  const std::vector<ValueCase> cases = value_cases(0.7f, ggx_distribution);
  if (!fail_first_wrong("ggx_distribution", cases, exact_distribution, 2)) return;
  // The fitted model: GGX or Beckmann, alpha as it is or not, with or without 1 / pi.
  if (const std::optional<DistributionModel> m = fit_distribution(cases)) {
    hint_together(m->changes());
    if (m->beckmann) add_hint({MessageId::microfacet_d_beckmann, {section(2)}});
    hint_alpha(m->alpha, 2);
    if (m->no_inverse_pi) add_hint({MessageId::microfacet_d_no_inverse_pi, {section(2)}});
    return;
  }
  // No model fits: say what the normalisation gives. The integral of D cos over the hemisphere
  // is pi times the integral of D over t = cos^2 in [0, 1] (d omega = 2 pi d cos, cos d cos = dt / 2).
  constexpr int kSteps = 400;
  constexpr float kAlpha = 0.25f;
  double integral = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double t = (i + 0.5) / kSteps;
    integral += ggx_distribution(direction(static_cast<float>(std::sqrt(t)), 0.3f), kAlpha);
  }
  integral *= kPiD / kSteps;
  if (std::isfinite(integral) && std::fabs(integral - 1.0) > 0.01)
    add_hint({MessageId::microfacet_d_integral, {{"integral", stream_text(integral)}, {"alpha", text(kAlpha)}, section(2)}});
}

// ---- G1 ------------------------------------------------------------------------------------

GRADED_TEST(kStage, Stage10Microfacet, SmithG1, 4) {
  const std::vector<ValueCase> cases = value_cases(2.1f, ggx_smith_g1);
  if (!fail_first_wrong("ggx_smith_g1", cases, exact_smith_g1, 3)) return;
  // The fitted model: no masking at all, or the numerator halved, tan not squared, alpha changed.
  if (const std::optional<SmithG1Model> m = fit_smith_g1(cases)) {
    hint_together(m->changes());
    if (m->no_masking) add_hint({MessageId::microfacet_g1_no_masking, {section(3)}});
    if (m->half) add_hint({MessageId::microfacet_g1_half, {section(3)}});
    if (m->tan_not_squared) add_hint({MessageId::microfacet_g1_tan_not_squared, {section(3)}});
    hint_alpha(m->alpha, 3);
  }
}

// ---- f -------------------------------------------------------------------------------------

GRADED_TEST(kStage, Stage10Microfacet, MicrofacetF, 6) {
  std::vector<FCase> cases = f_cases();
  for (FCase& k : cases) k.got = microfacet_f(k.wo, k.wi, k.alpha, k.specular);
  const FCase* wrong = nullptr;
  for (const FCase& k : cases)
    if (!close(k.got, exact_f(k))) {
      wrong = &k;
      break;
    }
  if (!wrong) return;
  fail_value(call_text("microfacet_f", {"wo " + text(wrong->wo), "wi " + text(wrong->wi), text(wrong->alpha),
                                        text(wrong->specular)}),
             text(wrong->got), text(glm::vec3(exact_f(*wrong))));
  if (hint_if_not_finite("microfacet_f", {wrong->got.x, wrong->got.y, wrong->got.z},
                         {MessageId::microfacet_advice_division, {section(4)}}))
    return;
  const auto f_right_where = [&](bool above) {
    return std::all_of(cases.begin(), cases.end(), [&](const FCase& k) {
      return (k.wo.z > 0.0f && k.wi.z > 0.0f) != above || close(k.got, exact_f(k));
    });
  };
  if (!hint_below_and_go_on("microfacet_f", f_right_where(true), f_right_where(false), 4)) return;
  // The fitted model, on the cases above the surface: D (exact or the student's), masking (exact,
  // the student's, none), the Fresnel cosine (dot(wi, h), wi.z, none: the specular colour, or 1)
  // and the factor 4 (there, missing).
  const bool own_d = !distribution_is_right(), own_g = !smith_g1_is_right();
  for (FCase& k : cases) {
    if (!(k.wo.z > 0.0f && k.wi.z > 0.0f)) continue;
    const glm::dvec3 h = half_vector_of(k.wo, k.wi);
    if (own_d) k.students_d = ggx_distribution(glm::vec3(h), k.alpha);
    if (own_g) k.students_g = double(ggx_smith_g1(k.wo, k.alpha)) * ggx_smith_g1(k.wi, k.alpha);
  }
  const std::optional<FModel> m = fit_f(cases, own_d, own_g);
  if (!m) return;
  hint_together(m->changes());
  if (m->students_d)
    add_hint({MessageId::microfacet_uses_your_function, {{"function", "microfacet_f"}, {"yours", "ggx_distribution"}}});
  if (m->masking == Masking::Students)
    add_hint({MessageId::microfacet_uses_your_function, {{"function", "microfacet_f"}, {"yours", "ggx_smith_g1"}}});
  if (m->masking == Masking::None) add_hint({MessageId::microfacet_f_no_masking, {section(4)}});
  if (m->fresnel == FresnelAt::Normal) add_hint({MessageId::microfacet_f_fresnel_at_normal, {section(4)}});
  if (m->fresnel == FresnelAt::NoAngle || m->fresnel == FresnelAt::None)
    add_hint({MessageId::microfacet_f_no_fresnel, {section(4)}});
  if (m->four_missing) add_hint({MessageId::microfacet_f_four_missing, {section(4)}});
}

// ---- The half vectors' density -------------------------------------------------------------

GRADED_TEST(kStage, Stage10Microfacet, HalfVectorPdf, 3) {
  const std::vector<ValueCase> cases = value_cases(1.3f, ggx_half_vector_pdf);
  if (!fail_first_wrong("ggx_half_vector_pdf", cases, exact_half_vector_pdf, 5)) return;
  const bool own_d = !distribution_is_right();
  std::vector<ValueCase> with_d = cases;
  if (own_d)
    for (ValueCase& k : with_d) k.students_d = ggx_distribution(k.vector, k.alpha);
  const std::optional<HalfVectorPdfModel> m = fit_half_vector_pdf(with_d, own_d);
  if (!m) return;
  if (m->students_d)
    add_hint({MessageId::microfacet_uses_your_function, {{"function", "ggx_half_vector_pdf"}, {"yours", "ggx_distribution"}}});
  if (m->no_cosine) add_hint({MessageId::microfacet_pdf_h_no_cosine, {section(5)}});
}

// ---- The samplers, by chi-square -----------------------------------------------------------

// The hints of a mistaken sampler's parts: its shape, and its alpha.
void hint_sampler(const SamplerModel& mistake) {
  hint_together(int(mistake.shape != SamplerShape::Ggx) + int(mistake.alpha != AlphaUse::AsIs));
  if (mistake.shape == SamplerShape::NoSquareRoot) add_hint({MessageId::microfacet_samples_no_sqrt, {section(5)}});
  if (mistake.shape == SamplerShape::Beckmann) add_hint({MessageId::microfacet_samples_beckmann, {section(5)}});
  if (mistake.shape == SamplerShape::UniformCosine) add_hint({MessageId::microfacet_samples_uniform, {section(5)}});
  hint_alpha(mistake.alpha, 5);
}

// The edges of [0, 1)^2 first (0 can happen, 1 never: the samples must stay finite and unit
// there), then random pairs.
std::vector<glm::vec2> uniform_inputs(const std::string& purpose) {
  const float below_one = std::nextafter(1.0f, 0.0f);
  std::vector<glm::vec2> inputs = {{0.0f, 0.0f}, {0.0f, 0.5f}, {0.5f, 0.0f}, {below_one, 0.0f},
                                   {0.0f, below_one}, {below_one, below_one}};
  Pcg32 random(test_seed(kSeed), testkit::stream_of(std::string(kStage) + "/" + purpose));
  while (inputs.size() < static_cast<std::size_t>(kSampleCount)) {
    const float a = random.next_float();
    const float b = random.next_float();
    inputs.push_back(glm::vec2(a, b));
  }
  return inputs;
}

// Checks every sample is a finite unit vector (and, when `above` is set, above the surface);
// fails and hints otherwise. Returns whether all are.
bool samples_in_domain(const char* function, const std::vector<glm::vec3>& samples, const std::vector<glm::vec2>& inputs,
                       bool above) {
  std::size_t bad = 0, first = 0;
  MessageId reason = MessageId::microfacet_reason_not_unit;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const glm::vec3& s = samples[i];
    std::optional<MessageId> why;
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z)) why = MessageId::microfacet_reason_not_finite;
    else if (std::fabs(glm::length(s) - 1.0f) > 1e-3f) why = MessageId::microfacet_reason_not_unit;
    else if (above && s.z < -1e-5f) why = MessageId::microfacet_reason_below;
    if (!why) continue;
    if (bad++ == 0) {
      first = i;
      reason = *why;
    }
  }
  if (bad == 0) return true;
  if (reason == MessageId::microfacet_reason_below) add_hint({MessageId::microfacet_half_vector_below, {section(5)}});
  add_failure({MessageId::microfacet_samples_outside,
               {{"function", function}, {"count", std::to_string(bad)}, {"total", std::to_string(samples.size())},
                {"u", text(glm::vec3(inputs[first], 0.0f))}, {"sample", text(samples[first])}, {"reason", Message(reason)}}});
  return false;
}

// Judges half vectors against GGX's density; on failure, fails naming `call` and hints the
// mistake whose density fits. Returns whether they follow it.
bool half_vectors_follow_ggx(const std::string& call, const std::vector<glm::dvec3>& half_vectors, double alpha) {
  std::vector<glm::dvec2> coordinates;
  coordinates.reserve(half_vectors.size());
  for (const glm::dvec3& h : half_vectors) coordinates.push_back(ggx_uniform_coordinates(h, alpha));
  bool passed = false;
  const double p = chi_square_p(coordinates, kLevel, &passed);
  if (passed) return true;
  add_failure({MessageId::microfacet_samples_misfit,
               {{"call", call}, {"count", std::to_string(half_vectors.size())}, {"p", stream_text(p)}}});
  if (const std::optional<SamplerModel> mistake = fit_sampler(half_vectors, alpha)) hint_sampler(*mistake);
  return false;
}

// Whether half vectors follow the density of GGX's visible normals seen from wo (Heitz's
// sampling, which the contract rules out): G1(wo) max(0, wo . h) D(h) / wo.z per steradian, so
// G1(wo) max(0, wo . h) / (wo.z cos(theta_h)) in the coordinates where D(h) cos(theta_h) is
// uniform. From wo along the normal it is D(h) cos(theta_h) itself; only an oblique wo tells.
bool half_vectors_follow_visible_normals(const glm::vec3& wo, const std::vector<glm::dvec3>& half_vectors, double alpha) {
  std::vector<glm::dvec2> coordinates;
  coordinates.reserve(half_vectors.size());
  for (const glm::dvec3& h : half_vectors) coordinates.push_back(ggx_uniform_coordinates(h, alpha));
  const glm::dvec3 o(wo);
  const double g1 = smith_g1(o.z, alpha);
  const auto density = [&](double share, double phi) {
    const double tan2 = alpha * alpha * share / std::max(1e-300, 1.0 - share);
    const double cos_h = 1.0 / std::sqrt(1.0 + tan2), sin_h = std::sqrt(std::max(0.0, 1.0 - cos_h * cos_h));
    const glm::dvec3 h(sin_h * std::cos(2.0 * kPiD * phi), sin_h * std::sin(2.0 * kPiD * phi), cos_h);
    return g1 * std::max(0.0, glm::dot(o, h)) / (o.z * cos_h);
  };
  bool fits = false;
  (void)chi_square_p(coordinates, kMistakeLevel, &fits, density);
  return fits;
}

// Whether the student's sample_ggx_half_vector passes (asked once; sample_microfacet_wi's hints name it).
bool half_vector_sampler_is_right(bool report) {
  static std::optional<bool> right;
  if (right && !report) return *right;
  bool all = true;
  for (const float alpha : {0.125f, 0.5f}) {
    const std::vector<glm::vec2> inputs = uniform_inputs("half_vectors/" + std::to_string(alpha));
    const std::vector<glm::vec3> samples = ggx_half_vector_samples(alpha, inputs);
    if (!samples_in_domain("sample_ggx_half_vector", samples, inputs, true)) {
      all = false;
      if (report) continue;
      break;
    }
    std::vector<glm::dvec3> half_vectors(samples.begin(), samples.end());
    if (report) {
      if (!half_vectors_follow_ggx(call_text("sample_ggx_half_vector", {"u", text(alpha)}), half_vectors, alpha)) all = false;
    } else {
      std::vector<glm::dvec2> coordinates;
      for (const glm::dvec3& h : half_vectors) coordinates.push_back(ggx_uniform_coordinates(h, alpha));
      bool passed = false;
      (void)chi_square_p(coordinates, kLevel, &passed);
      if (!passed) {
        all = false;
        break;
      }
    }
  }
  right = all;
  return all;
}

GRADED_TEST(kStage, Stage10Microfacet, HalfVectorSamples, 5) { (void)half_vector_sampler_is_right(true); }

GRADED_TEST(kStage, Stage10Microfacet, MicrofacetWiSamples, 4) {
  const glm::vec3 outgoing[] = {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(0.6f, 0.2f, 0.5f))};
  constexpr float kAlpha = 0.25f;
  bool all = true;
  for (int w = 0; w < 2; ++w) {
    const glm::vec3& wo = outgoing[w];
    const std::vector<glm::vec2> inputs = uniform_inputs("wi/" + std::to_string(w));
    const std::vector<glm::vec3> samples = microfacet_wi_samples(wo, kAlpha, inputs);
    if (!samples_in_domain("sample_microfacet_wi", samples, inputs, false)) {
      all = false;
      continue;
    }
    // Each wi back to its half vector, the one above the surface.
    auto half_vectors_of = [&](double sign) {
      std::vector<glm::dvec3> half_vectors;
      half_vectors.reserve(samples.size());
      for (const glm::vec3& wi : samples) {
        glm::dvec3 sum = glm::dvec3(wo) + sign * glm::dvec3(wi);
        const double length = glm::length(sum);
        sum = length > 0.0 ? sum / length : glm::dvec3(0, 0, 1);
        half_vectors.push_back(sum.z < 0.0 ? -sum : sum);
      }
      return half_vectors;
    };
    const std::string call = call_text("sample_microfacet_wi", {"wo " + text(wo), "u", text(kAlpha)});
    if (half_vectors_follow_ggx(call, half_vectors_of(1.0), kAlpha)) continue;
    all = false;
    // wi mirrored the wrong way (wo - 2 (wo . h) h): then normalize(wo - wi) is the half vector.
    std::vector<glm::dvec2> coordinates;
    for (const glm::dvec3& h : half_vectors_of(-1.0)) coordinates.push_back(ggx_uniform_coordinates(h, kAlpha));
    bool fits = false;
    (void)chi_square_p(coordinates, kMistakeLevel, &fits);
    if (fits) add_hint({MessageId::microfacet_wi_sign, {section(6)}});
    // wi is the half vector itself.
    coordinates.clear();
    for (const glm::vec3& wi : samples) coordinates.push_back(ggx_uniform_coordinates(glm::dvec3(wi), kAlpha));
    (void)chi_square_p(coordinates, kMistakeLevel, &fits);
    if (fits) add_hint({MessageId::microfacet_wi_is_half_vector, {section(6)}});
    if (wo.z < 1.0f && half_vectors_follow_visible_normals(wo, half_vectors_of(1.0), kAlpha))
      add_hint({MessageId::microfacet_wi_visible_normals, {section(6)}});
    // No wi below the surface at all: GGX's half vectors at this alpha make about 6% of them (one
    // more than 45 degrees from the normal mirrors wo below), so they were flipped or replaced.
    if (std::none_of(samples.begin(), samples.end(), [](const glm::vec3& wi) { return wi.z < 0.0f; }))
      add_hint({MessageId::microfacet_wi_none_below, {section(6)}});
  }
  if (!all && !half_vector_sampler_is_right(false))
    add_hint({MessageId::microfacet_uses_your_function, {{"function", "sample_microfacet_wi"}, {"yours", "sample_ggx_half_vector"}}});
}

// ---- wi's density ----------------------------------------------------------------------------

GRADED_TEST(kStage, Stage10Microfacet, MicrofacetPdf, 3) {
  std::vector<PdfCase> cases;
  for (const FCase& k : f_cases()) cases.push_back({k.wo, k.wi, k.alpha, microfacet_pdf(k.wo, k.wi, k.alpha)});
  const auto exact = [](const PdfCase& k) { return pdf_value(PdfModel{}, k); };
  const auto wrong = std::find_if(cases.begin(), cases.end(), [&](const PdfCase& k) { return !close(k.got, exact(k)); });
  if (wrong == cases.end()) return;
  fail_value(call_text("microfacet_pdf", {"wo " + text(wrong->wo), "wi " + text(wrong->wi), text(wrong->alpha)}),
             text(wrong->got), text(static_cast<float>(exact(*wrong))));
  if (hint_if_not_finite("microfacet_pdf", {wrong->got}, {MessageId::microfacet_advice_division, {section(6)}})) return;
  const auto right_where = [&](bool above) {
    return std::all_of(cases.begin(), cases.end(), [&](const PdfCase& k) {
      return (k.wo.z > 0.0f && k.wi.z > 0.0f) != above || close(k.got, exact(k));
    });
  };
  if (!hint_below_and_go_on("microfacet_pdf", right_where(true), right_where(false), 6)) return;
  const bool own_pdf_h = !all_close(value_cases(1.3f, ggx_half_vector_pdf), exact_half_vector_pdf);
  if (own_pdf_h)
    for (PdfCase& k : cases)
      if (k.wo.z > 0.0f && k.wi.z > 0.0f) k.students_pdf_h = ggx_half_vector_pdf(glm::vec3(half_vector_of(k.wo, k.wi)), k.alpha);
  const std::optional<PdfModel> m = fit_pdf(cases, own_pdf_h);
  if (!m) return;
  if (m->students_pdf_h)
    add_hint({MessageId::microfacet_uses_your_function, {{"function", "microfacet_pdf"}, {"yours", "ggx_half_vector_pdf"}}});
  if (m->jacobian == Jacobian::Missing) add_hint({MessageId::microfacet_pdf_no_jacobian, {section(6)}});
  if (m->jacobian == Jacobian::AtNormal) add_hint({MessageId::microfacet_pdf_jacobian_at_normal, {section(6)}});
  if (m->jacobian == Jacobian::FourMissing) add_hint({MessageId::microfacet_pdf_four_missing, {section(6)}});
}

}  // namespace
}  // namespace raylab::grading
