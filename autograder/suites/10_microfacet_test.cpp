// Autograder suite for stage 10_microfacet (bonus, 30 points).
//
// The values (D, G1, f and both densities) are judged against the exact formulas in double
// precision (float tolerances). A wrong function is diagnosed from a fitted model of what it
// computed: a small family of formulas, each a product of parts (which distribution, which
// alpha, whether 1 / pi, the masking, the Fresnel cosine, the factor 4, the Jacobian), and the
// judge looks for the member that reproduces EVERY value the student returned, fewest changed
// parts first. Each changed part is a hint of its own, so two mistakes at once get two hints;
// a part that is the student's own wrong function (f built on a wrong D) names that function,
// not f.
//
// The samplers run in bulk in the stage server (10_microfacet_calls.h). The judge maps every
// half vector (for sample_microfacet_wi: h = normalize(wo + wi)) to the coordinates in which
// GGX's density D(h) cos(theta_h) is uniform, (tan^2 / (alpha^2 + tan^2), phi / 2 pi), and
// chi-square tests them on a 16 x 16 grid. A sampler that fails is held against the densities of
// the known mistakes the same way; the one that fits (p above 1e-6) names the hint.
//
// False failures: the 4 chi-square tests share kGraderFalseFailureRate (1 in 1,000 for the stage,
// Sidak-corrected); the value tests are exact checks with tolerances for float rounding, which a
// correct implementation never fails.
#include "10_microfacet_calls.h"
#include "grading.h"
#include "support.h"

#include "raylab/error.h"
#include "raylab/random.h"
#include "raylab/stages/10_microfacet.h"
#include "raylab/testkit/statistics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "10_microfacet";
constexpr double kPiD = 3.14159265358979323846;
constexpr int kSampleCount = 100000;
constexpr int kGrid = 16;
constexpr std::uint64_t kSeed = 10;
const double kLevel = testkit::sidak_level(testkit::kGraderFalseFailureRate, 4);
constexpr double kMistakeLevel = 1e-6;  // a mistake's density "fits" the samples above this p

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

bool close(double got, double expected, double relative = 2e-4) {
  return std::fabs(got - expected) <= relative * std::fabs(expected) + 1e-6;
}

// ---- The exact formulas, in double, with the parts a mistake may change ------------------

enum class AlphaUse { AsIs, SquaredFirst, SquareRoot };  // alpha, alpha^2 or sqrt(alpha) in its place
double alpha_used(double alpha, AlphaUse use) {
  return use == AlphaUse::AsIs ? alpha : use == AlphaUse::SquaredFirst ? alpha * alpha : std::sqrt(alpha);
}

double ggx_d(double cos_h, double alpha) {
  if (!(cos_h > 0.0)) return 0.0;
  const double a2 = alpha * alpha, denominator = (a2 - 1.0) * cos_h * cos_h + 1.0;
  return a2 / (kPiD * denominator * denominator);
}
double beckmann_d(double cos_h, double alpha) {
  if (!(cos_h > 0.0)) return 0.0;
  const double c2 = cos_h * cos_h, a2 = alpha * alpha;
  return std::exp(-(1.0 - c2) / (c2 * a2)) / (kPiD * a2 * c2 * c2);
}
double smith_g1(double cos_v, double alpha, bool tan_squared = true) {
  if (!(cos_v > 0.0)) return 0.0;
  const double c2 = std::min(1.0, cos_v * cos_v), tan2 = (1.0 - c2) / c2;
  return 2.0 / (1.0 + std::sqrt(1.0 + alpha * alpha * (tan_squared ? tan2 : std::sqrt(tan2))));
}
glm::dvec3 half_vector_of(const glm::vec3& wo, const glm::vec3& wi) {
  const glm::dvec3 sum = glm::dvec3(wo) + glm::dvec3(wi);
  return sum / glm::length(sum);
}
double schlick(double specular, double cosine) {
  const double m = 1.0 - std::clamp(cosine, 0.0, 1.0);
  return specular + (1.0 - specular) * m * m * m * m * m;
}

// A unit vector at angle theta from the normal (cos_theta), azimuth phi.
glm::vec3 direction(float cos_theta, float phi) {
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  return glm::vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

const float kAlphas[] = {0.0625f, 0.25f, 0.75f};
const float kCosines[] = {1.0f, 0.97f, 0.85f, 0.6f, 0.3f, 0.08f, 0.0f, -0.4f};

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

struct ValueCase {
  glm::vec3 vector;
  float alpha;
  float got;
};

// Fails with the first case whose value is not exact(case). Returns whether the diagnosis should
// go on: false when every value is right, or when it is done here (a value not finite; only the
// values below the surface wrong, which must be 0).
template <typename Exact>
bool fail_first_wrong(const char* function, const std::vector<ValueCase>& cases, const Exact& exact, int section_number) {
  const auto wrong = std::find_if(cases.begin(), cases.end(), [&](const ValueCase& k) { return !close(k.got, exact(k)); });
  if (wrong == cases.end()) return false;
  fail_value(call_text(function, {text(wrong->vector), text(wrong->alpha)}), text(wrong->got),
             text(static_cast<float>(exact(*wrong))));
  if (hint_if_not_finite(function, {wrong->got}, {MessageId::microfacet_advice_division, {section(section_number)}}))
    return false;
  if (std::all_of(cases.begin(), cases.end(),
                  [&](const ValueCase& k) { return k.vector.z <= 0.0f || close(k.got, exact(k)); })) {
    add_hint({MessageId::microfacet_below_not_zero, {{"function", function}, section(section_number)}});
    return false;
  }
  return true;
}

// The student's function(direction, alpha) at every alpha of kAlphas and cosine of kCosines
// (directions at azimuth phi).
template <typename Function>
std::vector<ValueCase> value_cases(float phi, const Function& function) {
  std::vector<ValueCase> cases;
  for (const float alpha : kAlphas)
    for (const float c : kCosines) {
      const glm::vec3 v = direction(c, phi);
      cases.push_back({v, alpha, function(v, alpha)});
    }
  return cases;
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
  struct Model {
    bool beckmann;
    AlphaUse alpha;
    bool no_inverse_pi;
    int changes() const { return int(beckmann) + int(alpha != AlphaUse::AsIs) + int(no_inverse_pi); }
  };
  std::vector<Model> models;
  for (const bool beckmann : {false, true})
    for (const AlphaUse use : {AlphaUse::AsIs, AlphaUse::SquaredFirst, AlphaUse::SquareRoot})
      for (const bool no_pi : {false, true}) models.push_back({beckmann, use, no_pi});
  std::stable_sort(models.begin(), models.end(), [](const Model& a, const Model& b) { return a.changes() < b.changes(); });
  for (const Model& m : models) {
    if (m.changes() == 0) continue;
    const bool fits = std::all_of(cases.begin(), cases.end(), [&](const ValueCase& k) {
      const double a = alpha_used(k.alpha, m.alpha);
      const double d = (m.beckmann ? beckmann_d(k.vector.z, a) : ggx_d(k.vector.z, a)) * (m.no_inverse_pi ? kPiD : 1.0);
      return close(k.got, d, 1e-3);
    });
    if (!fits) continue;
    if (m.beckmann) add_hint({MessageId::microfacet_d_beckmann, {section(2)}});
    hint_alpha(m.alpha, 2);
    if (m.no_inverse_pi) add_hint({MessageId::microfacet_d_no_inverse_pi, {section(2)}});
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
  if (std::all_of(cases.begin(), cases.end(), [](const ValueCase& k) { return k.vector.z <= 0.0f || close(k.got, 1.0); })) {
    add_hint({MessageId::microfacet_g1_no_masking, {section(3)}});
    return;
  }
  if (std::all_of(cases.begin(), cases.end(), [](const ValueCase& k) {
        return k.vector.z <= 0.0f || close(k.got, 0.5 * smith_g1(k.vector.z, k.alpha), 1e-3);
      })) {
    add_hint({MessageId::microfacet_g1_half, {section(3)}});
    return;
  }
  for (const bool tan_squared : {true, false})
    for (const AlphaUse use : {AlphaUse::AsIs, AlphaUse::SquaredFirst, AlphaUse::SquareRoot}) {
      if (tan_squared && use == AlphaUse::AsIs) continue;
      const bool fits = std::all_of(cases.begin(), cases.end(), [&](const ValueCase& k) {
        return close(k.got, smith_g1(k.vector.z, alpha_used(k.alpha, use), tan_squared), 1e-3);
      });
      if (!fits) continue;
      if (!tan_squared) add_hint({MessageId::microfacet_g1_tan_not_squared, {section(3)}});
      hint_alpha(use, 3);
      return;
    }
}

// ---- f -------------------------------------------------------------------------------------

struct FCase {
  glm::vec3 wo, wi;
  float alpha;
  glm::vec3 specular;
  glm::vec3 got;
  // The student's own D(h), G1(wo) and G1(wi), for the model built on them.
  double student_d = 0.0, student_g = 0.0;
};

std::vector<FCase> f_cases() {
  const glm::vec3 copper(0.955f, 0.638f, 0.538f), plastic(0.04f);
  std::vector<FCase> cases;
  Pcg32 random(kSeed, testkit::stream_of(std::string(kStage) + "/f"));
  for (const float alpha : kAlphas) {
    cases.push_back({glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), alpha, copper, {}});
    const glm::vec3 wo = direction(0.5f, 0.4f);
    cases.push_back({wo, glm::vec3(-wo.x, -wo.y, wo.z), alpha, copper, {}});  // the mirror direction
    cases.push_back({direction(0.9f, 1.0f), direction(0.15f, 3.5f), alpha, plastic, {}});
    for (int i = 0; i < 3; ++i) {
      const float co = 0.1f + 0.9f * random.next_float(), po = 6.2831853f * random.next_float();
      const float ci = 0.1f + 0.9f * random.next_float(), phi_i = 6.2831853f * random.next_float();
      cases.push_back({direction(co, po), direction(ci, phi_i), alpha, i == 0 ? plastic : copper, {}});
    }
    cases.push_back({direction(0.7f, 0.0f), direction(-0.3f, 2.0f), alpha, copper, {}});  // wi below
    cases.push_back({direction(-0.2f, 0.0f), direction(0.8f, 2.0f), alpha, copper, {}});  // wo below
  }
  return cases;
}

glm::dvec3 exact_f(const FCase& k) {
  if (!(k.wo.z > 0.0f) || !(k.wi.z > 0.0f)) return glm::dvec3(0.0);
  const glm::dvec3 h = half_vector_of(k.wo, k.wi);
  const double shape = ggx_d(h.z, k.alpha) * smith_g1(k.wo.z, k.alpha) * smith_g1(k.wi.z, k.alpha) /
                       (4.0 * double(k.wo.z) * double(k.wi.z));
  const double c = glm::dot(glm::dvec3(k.wi), h);
  return glm::dvec3(schlick(k.specular.x, c), schlick(k.specular.y, c), schlick(k.specular.z, c)) * shape;
}

bool close(const glm::vec3& got, const glm::dvec3& expected, double relative = 2e-4) {
  return close(got.x, expected.x, relative) && close(got.y, expected.y, relative) && close(got.z, expected.z, relative);
}

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
  if (std::all_of(cases.begin(), cases.end(), [](const FCase& k) {
        return (k.wo.z > 0.0f && k.wi.z > 0.0f) == false || close(k.got, exact_f(k));
      })) {
    add_hint({MessageId::microfacet_below_not_zero, {{"function", "microfacet_f"}, section(4)}});
    return;
  }
  // The fitted model, on the cases above the surface: D (exact or the student's), masking (exact,
  // the student's, none), the Fresnel cosine (dot(wi, h), wi.z, none: the specular colour, or 1)
  // and the factor 4 (there, missing).
  const bool own_d = !distribution_is_right(), own_g = !smith_g1_is_right();
  for (FCase& k : cases) {
    if (!(k.wo.z > 0.0f && k.wi.z > 0.0f)) continue;
    const glm::dvec3 h = half_vector_of(k.wo, k.wi);
    if (own_d) k.student_d = ggx_distribution(glm::vec3(h), k.alpha);
    if (own_g) k.student_g = double(ggx_smith_g1(k.wo, k.alpha)) * ggx_smith_g1(k.wi, k.alpha);
  }
  enum class Masking { Exact, Students, None };
  enum class FresnelAt { HalfVector, Normal, NoAngle, None };
  struct Model {
    bool students_d;
    Masking masking;
    FresnelAt fresnel;
    bool four_missing;
    int changes() const {
      return int(masking == Masking::None) + int(fresnel != FresnelAt::HalfVector) + int(four_missing);
    }
  };
  std::vector<Model> models;
  for (const bool d : {false, true}) {
    if (d && !own_d) continue;
    for (const Masking g : {Masking::Exact, Masking::Students, Masking::None}) {
      if (g == Masking::Students && !own_g) continue;
      for (const FresnelAt fr : {FresnelAt::HalfVector, FresnelAt::Normal, FresnelAt::NoAngle, FresnelAt::None})
        for (const bool four : {false, true}) models.push_back({d, g, fr, four});
    }
  }
  std::stable_sort(models.begin(), models.end(), [](const Model& a, const Model& b) { return a.changes() < b.changes(); });
  for (const Model& m : models) {
    if (m.changes() == 0 && !m.students_d && m.masking == Masking::Exact) continue;  // the exact f
    const bool fits = std::all_of(cases.begin(), cases.end(), [&](const FCase& k) {
      if (!(k.wo.z > 0.0f && k.wi.z > 0.0f)) return true;
      const glm::dvec3 h = half_vector_of(k.wo, k.wi);
      const double d = m.students_d ? k.student_d : ggx_d(h.z, k.alpha);
      const double g = m.masking == Masking::Students ? k.student_g
                       : m.masking == Masking::None   ? 1.0
                                                      : smith_g1(k.wo.z, k.alpha) * smith_g1(k.wi.z, k.alpha);
      const double shape = d * g / ((m.four_missing ? 1.0 : 4.0) * double(k.wo.z) * double(k.wi.z));
      const double c = m.fresnel == FresnelAt::Normal ? double(k.wi.z) : glm::dot(glm::dvec3(k.wi), h);
      auto fresnel = [&](double specular) {
        return m.fresnel == FresnelAt::None ? 1.0 : m.fresnel == FresnelAt::NoAngle ? specular : schlick(specular, c);
      };
      return close(k.got, glm::dvec3(fresnel(k.specular.x), fresnel(k.specular.y), fresnel(k.specular.z)) * shape, 1e-3);
    });
    if (!fits) continue;
    if (m.students_d) add_hint({MessageId::microfacet_uses_your_function, {{"function", "microfacet_f"}, {"yours", "ggx_distribution"}}});
    if (m.masking == Masking::Students)
      add_hint({MessageId::microfacet_uses_your_function, {{"function", "microfacet_f"}, {"yours", "ggx_smith_g1"}}});
    if (m.masking == Masking::None) add_hint({MessageId::microfacet_f_no_masking, {section(4)}});
    if (m.fresnel == FresnelAt::Normal) add_hint({MessageId::microfacet_f_fresnel_at_normal, {section(4)}});
    if (m.fresnel == FresnelAt::NoAngle || m.fresnel == FresnelAt::None)
      add_hint({MessageId::microfacet_f_no_fresnel, {section(4)}});
    if (m.four_missing) add_hint({MessageId::microfacet_f_four_missing, {section(4)}});
    return;
  }
}

// ---- The half vectors' density -------------------------------------------------------------

GRADED_TEST(kStage, Stage10Microfacet, HalfVectorPdf, 3) {
  const std::vector<ValueCase> cases = value_cases(1.3f, ggx_half_vector_pdf);
  if (!fail_first_wrong("ggx_half_vector_pdf", cases, exact_half_vector_pdf, 5)) return;
  const bool own_d = !distribution_is_right();
  for (const bool students_d : {false, true}) {
    if (students_d && !own_d) continue;
    for (const bool cosine : {true, false}) {
      if (cosine && !students_d) continue;  // the exact density
      const bool fits = std::all_of(cases.begin(), cases.end(), [&](const ValueCase& k) {
        if (!(k.vector.z > 0.0f)) return k.got == 0.0f;
        const double d = students_d ? ggx_distribution(k.vector, k.alpha) : ggx_d(k.vector.z, k.alpha);
        return close(k.got, d * (cosine ? k.vector.z : 1.0f), 1e-3);
      });
      if (!fits) continue;
      if (students_d)
        add_hint({MessageId::microfacet_uses_your_function, {{"function", "ggx_half_vector_pdf"}, {"yours", "ggx_distribution"}}});
      if (!cosine) add_hint({MessageId::microfacet_pdf_h_no_cosine, {section(5)}});
      return;
    }
  }
}

// ---- The samplers, by chi-square -----------------------------------------------------------

// The coordinates in which half vectors of density D(h) cos(theta_h) (GGX of `alpha`) are
// uniform in [0, 1)^2: the share of that density within theta, tan^2 / (alpha^2 + tan^2), and
// phi / 2 pi.
glm::dvec2 ggx_uniform_coordinates(const glm::dvec3& h, double alpha) {
  const double c2 = h.z * h.z, s2 = std::max(0.0, 1.0 - c2);
  const double share = s2 / (alpha * alpha * c2 + s2);
  double phi = std::atan2(h.y, h.x) / (2.0 * kPiD);
  if (phi < 0.0) phi += 1.0;
  return {share, phi};
}

// The same for mistaken samplers whose density is known: each maps a half vector to
// coordinates that are uniform if the sampler made that mistake.
struct SamplerMistake {
  std::function<glm::dvec2(const glm::dvec3& h, double alpha)> coordinates;
  std::function<void()> hint;
};
std::vector<SamplerMistake> sampler_mistakes() {
  auto ggx_with = [](AlphaUse use) {
    return [use](const glm::dvec3& h, double alpha) { return ggx_uniform_coordinates(h, alpha_used(alpha, use)); };
  };
  auto phi_of = [](const glm::dvec3& h) { return ggx_uniform_coordinates(h, 1.0).y; };
  return {
      {ggx_with(AlphaUse::SquaredFirst), [] { hint_alpha(AlphaUse::SquaredFirst, 5); }},
      {ggx_with(AlphaUse::SquareRoot), [] { hint_alpha(AlphaUse::SquareRoot, 5); }},
      // tan(theta) = alpha u / (1 - u): the square root of tan^2 = alpha^2 u / (1 - u) missing.
      {[phi_of](const glm::dvec3& h, double alpha) {
         const double c = std::max(h.z, 1e-12), tan = std::sqrt(std::max(0.0, 1.0 - c * c)) / c;
         return glm::dvec2(tan / (alpha + tan), phi_of(h));
       },
       [] { add_hint({MessageId::microfacet_samples_no_sqrt, {section(5)}}); }},
      // Beckmann's sampling: tan^2 = -alpha^2 log(1 - u).
      {[phi_of](const glm::dvec3& h, double alpha) {
         const double c2 = std::max(h.z * h.z, 1e-24);
         return glm::dvec2(1.0 - std::exp(-(1.0 - c2) / (c2 * alpha * alpha)), phi_of(h));
       },
       [] { add_hint({MessageId::microfacet_samples_beckmann, {section(5)}}); }},
      // cos(theta) uniform: the hemisphere's uniform warp, not GGX's.
      {[phi_of](const glm::dvec3& h, double) { return glm::dvec2(1.0 - h.z, phi_of(h)); },
       [] { add_hint({MessageId::microfacet_samples_uniform, {section(5)}}); }},
  };
}

// The chi-square test of coordinates in [0, 1)^2 on the 16 x 16 grid against `density` there
// (uniform when none is given).
double chi_square_p(const std::vector<glm::dvec2>& coordinates, double level, bool* passed,
                    const std::function<double(double u, double v)>& density = nullptr) {
  testkit::Histogram2D histogram(kGrid, kGrid, 0.0, 1.0, 0.0, 1.0);
  for (const glm::dvec2& c : coordinates) histogram.add(c.x, c.y);
  const double count = static_cast<double>(coordinates.size());
  const std::vector<double> expected = density ? histogram.expected_counts(density, count, 12)
                                               : std::vector<double>(static_cast<std::size_t>(kGrid * kGrid),
                                                                     count / (kGrid * kGrid));
  std::vector<double> observed = histogram.counts();
  const testkit::ChiSquareResult result = testkit::chi_square_test(observed, expected, level);
  if (histogram.outside() > 0) {
    *passed = false;
    return 0.0;
  }
  *passed = result.passed;
  return result.p_value;
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
  for (const SamplerMistake& mistake : sampler_mistakes()) {
    coordinates.clear();
    for (const glm::dvec3& h : half_vectors) coordinates.push_back(mistake.coordinates(h, alpha));
    bool fits = false;
    (void)chi_square_p(coordinates, kMistakeLevel, &fits);
    if (fits) {
      mistake.hint();
      break;
    }
  }
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
  struct Case {
    glm::vec3 wo, wi;
    float alpha;
    float got;
  };
  std::vector<Case> cases;
  for (const FCase& k : f_cases()) cases.push_back({k.wo, k.wi, k.alpha, microfacet_pdf(k.wo, k.wi, k.alpha)});
  enum class Jacobian { Right, Missing, AtNormal, FourMissing };
  auto model = [](const Case& k, bool students_pdf_h, Jacobian jacobian) {
    if (!(k.wo.z > 0.0f) || !(k.wi.z > 0.0f)) return 0.0;
    const glm::dvec3 h = half_vector_of(k.wo, k.wi);
    const double pdf_h = students_pdf_h ? ggx_half_vector_pdf(glm::vec3(h), k.alpha) : ggx_d(h.z, k.alpha) * h.z;
    const double wo_h = std::fabs(glm::dot(glm::dvec3(k.wo), h));
    switch (jacobian) {
      case Jacobian::Right: return pdf_h / (4.0 * wo_h);
      case Jacobian::Missing: return pdf_h;
      case Jacobian::AtNormal: return pdf_h / (4.0 * k.wi.z);
      case Jacobian::FourMissing: return pdf_h / wo_h;
    }
    return 0.0;
  };
  const Case* wrong = nullptr;
  for (const Case& k : cases)
    if (!close(k.got, model(k, false, Jacobian::Right))) {
      wrong = &k;
      break;
    }
  if (!wrong) return;
  fail_value(call_text("microfacet_pdf", {"wo " + text(wrong->wo), "wi " + text(wrong->wi), text(wrong->alpha)}),
             text(wrong->got), text(static_cast<float>(model(*wrong, false, Jacobian::Right))));
  if (hint_if_not_finite("microfacet_pdf", {wrong->got}, {MessageId::microfacet_advice_division, {section(6)}})) return;
  if (std::all_of(cases.begin(), cases.end(), [&](const Case& k) {
        return (k.wo.z > 0.0f && k.wi.z > 0.0f) == false || close(k.got, model(k, false, Jacobian::Right));
      })) {
    add_hint({MessageId::microfacet_below_not_zero, {{"function", "microfacet_pdf"}, section(6)}});
    return;
  }
  const bool own_pdf_h = !all_close(value_cases(1.3f, ggx_half_vector_pdf), exact_half_vector_pdf);
  for (const Jacobian jacobian : {Jacobian::Right, Jacobian::Missing, Jacobian::AtNormal, Jacobian::FourMissing})
    for (const bool students : {false, true}) {
      if ((students && !own_pdf_h) || (!students && jacobian == Jacobian::Right)) continue;
      const bool fits = std::all_of(cases.begin(), cases.end(), [&](const Case& k) {
        return (k.wo.z > 0.0f && k.wi.z > 0.0f) == false || close(k.got, model(k, students, jacobian), 1e-3);
      });
      if (!fits) continue;
      if (students)
        add_hint({MessageId::microfacet_uses_your_function, {{"function", "microfacet_pdf"}, {"yours", "ggx_half_vector_pdf"}}});
      if (jacobian == Jacobian::Missing) add_hint({MessageId::microfacet_pdf_no_jacobian, {section(6)}});
      if (jacobian == Jacobian::AtNormal) add_hint({MessageId::microfacet_pdf_jacobian_at_normal, {section(6)}});
      if (jacobian == Jacobian::FourMissing) add_hint({MessageId::microfacet_pdf_four_missing, {section(6)}});
      return;
    }
}

}  // namespace
}  // namespace raylab::grading
