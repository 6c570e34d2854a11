#include "microfacet_models.h"

#include "raylab/random.h"
#include "raylab/testkit/random_values.h"
#include "raylab/testkit/statistics.h"

#include <algorithm>
#include <cmath>

namespace raylab::grading::microfacet {

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
double smith_g1(double cos_v, double alpha, bool tan_squared) {
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
glm::vec3 direction(float cos_theta, float phi) {
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  return glm::vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

bool close(double got, double expected, double relative) {
  return std::fabs(got - expected) <= relative * std::fabs(expected) + 1e-6;
}
bool close(const glm::vec3& got, const glm::dvec3& expected, double relative) {
  return close(got.x, expected.x, relative) && close(got.y, expected.y, relative) && close(got.z, expected.z, relative);
}

const float kAlphas[3] = {0.0625f, 0.25f, 0.75f};
const float kCosines[8] = {1.0f, 0.97f, 0.85f, 0.6f, 0.3f, 0.08f, 0.0f, -0.4f};

std::vector<ValueCase> value_cases(float phi, const std::function<float(const glm::vec3&, float)>& function) {
  std::vector<ValueCase> cases;
  for (const float alpha : kAlphas)
    for (const float c : kCosines) {
      const glm::vec3 v = direction(c, phi);
      cases.push_back({v, alpha, function(v, alpha)});
    }
  return cases;
}

namespace {

// Every fit compares the values above the surface only: 0 below is a rule of its own, with its own
// hint (10_microfacet_test.cpp), so a mistake above is named whatever the values below are.
constexpr double kModelTolerance = 1e-3;

template <typename Model>
void sort_by_changes(std::vector<Model>& models) {
  std::stable_sort(models.begin(), models.end(), [](const Model& a, const Model& b) { return a.changes() < b.changes(); });
}

const AlphaUse kAlphaUses[] = {AlphaUse::AsIs, AlphaUse::SquaredFirst, AlphaUse::SquareRoot};

// The first of `models` (in their order, fewest changed parts first) but the exact one whose
// value(model, cosine, alpha) matches every case above the surface.
template <typename Model>
std::optional<Model> first_fitting(const std::vector<Model>& models, const std::vector<ValueCase>& cases,
                                   double (*value)(const Model&, double, double)) {
  for (const Model& m : models) {
    if (m.changes() == 0) continue;
    if (std::all_of(cases.begin(), cases.end(), [&](const ValueCase& k) {
          return !(k.vector.z > 0.0f) || close(k.got, value(m, k.vector.z, k.alpha), kModelTolerance);
        }))
      return m;
  }
  return std::nullopt;
}

}  // namespace

// ---- D -------------------------------------------------------------------------------------

std::vector<DistributionModel> distribution_models() {
  std::vector<DistributionModel> models;
  for (const bool beckmann : {false, true})
    for (const AlphaUse use : kAlphaUses)
      for (const bool no_pi : {false, true}) models.push_back({beckmann, use, no_pi});
  sort_by_changes(models);
  return models;
}

double distribution_value(const DistributionModel& m, double cos_h, double alpha) {
  const double a = alpha_used(alpha, m.alpha);
  return (m.beckmann ? beckmann_d(cos_h, a) : ggx_d(cos_h, a)) * (m.no_inverse_pi ? kPiD : 1.0);
}

std::optional<DistributionModel> fit_distribution(const std::vector<ValueCase>& cases) {
  return first_fitting(distribution_models(), cases, distribution_value);
}

// ---- G1 ------------------------------------------------------------------------------------

std::vector<SmithG1Model> smith_g1_models() {
  std::vector<SmithG1Model> models = {SmithG1Model{true, false, false, AlphaUse::AsIs}};
  for (const bool half : {false, true})
    for (const bool tan_not_squared : {false, true})
      for (const AlphaUse use : kAlphaUses) models.push_back({false, half, tan_not_squared, use});
  sort_by_changes(models);
  return models;
}

double smith_g1_value(const SmithG1Model& m, double cos_v, double alpha) {
  if (!(cos_v > 0.0)) return 0.0;
  if (m.no_masking) return 1.0;
  return (m.half ? 0.5 : 1.0) * smith_g1(cos_v, alpha_used(alpha, m.alpha), !m.tan_not_squared);
}

std::optional<SmithG1Model> fit_smith_g1(const std::vector<ValueCase>& cases) {
  return first_fitting(smith_g1_models(), cases, smith_g1_value);
}

// ---- f -------------------------------------------------------------------------------------

std::vector<FCase> f_cases() {
  const glm::vec3 copper(0.955f, 0.638f, 0.538f), plastic(0.04f);
  std::vector<FCase> cases;
  Pcg32 random(kStageSeed, testkit::stream_of("10_microfacet/f"));
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
  return f_value(FModel{}, k);
}

std::vector<FModel> f_models(bool own_d, bool own_g) {
  std::vector<FModel> models;
  for (const bool d : {false, true}) {
    if (d && !own_d) continue;
    for (const Masking g : {Masking::Exact, Masking::Students, Masking::None}) {
      if (g == Masking::Students && !own_g) continue;
      for (const FresnelAt fr : {FresnelAt::HalfVector, FresnelAt::Normal, FresnelAt::NoAngle, FresnelAt::None})
        for (const bool four : {false, true}) models.push_back({d, g, fr, four});
    }
  }
  sort_by_changes(models);
  return models;
}

glm::dvec3 f_value(const FModel& m, const FCase& k) {
  const glm::dvec3 h = half_vector_of(k.wo, k.wi);
  const double d = m.students_d ? k.students_d : ggx_d(h.z, k.alpha);
  const double g = m.masking == Masking::Students ? k.students_g
                   : m.masking == Masking::None   ? 1.0
                                                  : smith_g1(k.wo.z, k.alpha) * smith_g1(k.wi.z, k.alpha);
  const double shape = d * g / ((m.four_missing ? 1.0 : 4.0) * double(k.wo.z) * double(k.wi.z));
  const double c = m.fresnel == FresnelAt::Normal ? double(k.wi.z) : glm::dot(glm::dvec3(k.wi), h);
  auto fresnel = [&](double specular) {
    return m.fresnel == FresnelAt::None ? 1.0 : m.fresnel == FresnelAt::NoAngle ? specular : schlick(specular, c);
  };
  return glm::dvec3(fresnel(k.specular.x), fresnel(k.specular.y), fresnel(k.specular.z)) * shape;
}

std::optional<FModel> fit_f(const std::vector<FCase>& cases, bool own_d, bool own_g) {
  for (const FModel& m : f_models(own_d, own_g)) {
    if (m == FModel{}) continue;  // the exact f
    if (std::all_of(cases.begin(), cases.end(), [&](const FCase& k) {
          return !(k.wo.z > 0.0f && k.wi.z > 0.0f) || close(k.got, f_value(m, k), kModelTolerance);
        }))
      return m;
  }
  return std::nullopt;
}

// ---- The half vectors' density -----------------------------------------------------------

double half_vector_pdf_value(const HalfVectorPdfModel& m, const ValueCase& k) {
  if (!(k.vector.z > 0.0f)) return 0.0;
  const double d = m.students_d ? double(k.students_d) : ggx_d(k.vector.z, k.alpha);
  return d * (m.no_cosine ? 1.0 : double(k.vector.z));
}

std::optional<HalfVectorPdfModel> fit_half_vector_pdf(const std::vector<ValueCase>& cases, bool own_d) {
  for (const bool students_d : {false, true}) {
    if (students_d && !own_d) continue;
    for (const bool no_cosine : {false, true}) {
      if (!no_cosine && !students_d) continue;  // the exact density
      const HalfVectorPdfModel m{students_d, no_cosine};
      if (std::all_of(cases.begin(), cases.end(), [&](const ValueCase& k) {
            return !(k.vector.z > 0.0f) || close(k.got, half_vector_pdf_value(m, k), kModelTolerance);
          }))
        return m;
    }
  }
  return std::nullopt;
}

// ---- wi's density ------------------------------------------------------------------------

double pdf_value(const PdfModel& m, const PdfCase& k) {
  if (!(k.wo.z > 0.0f) || !(k.wi.z > 0.0f)) return 0.0;
  const glm::dvec3 h = half_vector_of(k.wo, k.wi);
  const double pdf_h = m.students_pdf_h ? k.students_pdf_h : ggx_d(h.z, k.alpha) * h.z;
  const double wo_h = std::fabs(glm::dot(glm::dvec3(k.wo), h));
  switch (m.jacobian) {
    case Jacobian::Right: return pdf_h / (4.0 * wo_h);
    case Jacobian::Missing: return pdf_h;
    case Jacobian::AtNormal: return pdf_h / (4.0 * k.wi.z);
    case Jacobian::FourMissing: return pdf_h / wo_h;
  }
  return 0.0;
}

std::optional<PdfModel> fit_pdf(const std::vector<PdfCase>& cases, bool own_pdf_h) {
  for (const Jacobian jacobian : {Jacobian::Right, Jacobian::Missing, Jacobian::AtNormal, Jacobian::FourMissing})
    for (const bool students : {false, true}) {
      if ((students && !own_pdf_h) || (!students && jacobian == Jacobian::Right)) continue;
      const PdfModel m{students, jacobian};
      if (std::all_of(cases.begin(), cases.end(), [&](const PdfCase& k) {
            return !(k.wo.z > 0.0f && k.wi.z > 0.0f) || close(k.got, pdf_value(m, k), kModelTolerance);
          }))
        return m;
    }
  return std::nullopt;
}

// ---- The samplers ----------------------------------------------------------------------------

glm::dvec2 ggx_uniform_coordinates(const glm::dvec3& h, double alpha) {
  const double c2 = h.z * h.z, s2 = std::max(0.0, 1.0 - c2);
  const double share = s2 / (alpha * alpha * c2 + s2);
  double phi = std::atan2(h.y, h.x) / (2.0 * kPiD);
  if (phi < 0.0) phi += 1.0;
  return {share, phi};
}

std::vector<SamplerModel> sampler_mistakes() {
  return {{SamplerShape::Ggx, AlphaUse::SquaredFirst},          {SamplerShape::Ggx, AlphaUse::SquareRoot},
          {SamplerShape::NoSquareRoot, AlphaUse::AsIs},         {SamplerShape::Beckmann, AlphaUse::AsIs},
          {SamplerShape::UniformCosine, AlphaUse::AsIs},        {SamplerShape::NoSquareRoot, AlphaUse::SquaredFirst},
          {SamplerShape::NoSquareRoot, AlphaUse::SquareRoot},   {SamplerShape::Beckmann, AlphaUse::SquaredFirst},
          {SamplerShape::Beckmann, AlphaUse::SquareRoot}};
}

glm::dvec2 sampler_coordinates(const SamplerModel& model, const glm::dvec3& h, double alpha) {
  const double a = alpha_used(alpha, model.alpha);
  const double phi = ggx_uniform_coordinates(h, 1.0).y;
  switch (model.shape) {
    case SamplerShape::Ggx: return ggx_uniform_coordinates(h, a);
    case SamplerShape::NoSquareRoot: {
      // tan(theta) = alpha u / (1 - u): the square root of tan^2 = alpha^2 u / (1 - u) missing.
      const double c = std::max(h.z, 1e-12), tan = std::sqrt(std::max(0.0, 1.0 - c * c)) / c;
      return {tan / (a + tan), phi};
    }
    case SamplerShape::Beckmann: {
      // Beckmann's sampling: tan^2 = -alpha^2 log(1 - u).
      const double c2 = std::max(h.z * h.z, 1e-24);
      return {1.0 - std::exp(-(1.0 - c2) / (c2 * a * a)), phi};
    }
    case SamplerShape::UniformCosine: return {1.0 - h.z, phi};  // the hemisphere's uniform warp
  }
  return {0.0, 0.0};
}

glm::dvec3 sample_with(const SamplerModel& model, const glm::dvec2& u, double alpha) {
  const double a = alpha_used(alpha, model.alpha);
  double cos_theta = 1.0;
  switch (model.shape) {
    case SamplerShape::Ggx: cos_theta = 1.0 / std::sqrt(1.0 + a * a * u.x / (1.0 - u.x)); break;
    case SamplerShape::NoSquareRoot: {
      const double tan = a * u.x / (1.0 - u.x);
      cos_theta = 1.0 / std::sqrt(1.0 + tan * tan);
      break;
    }
    case SamplerShape::Beckmann: cos_theta = 1.0 / std::sqrt(1.0 - a * a * std::log(1.0 - u.x)); break;
    case SamplerShape::UniformCosine: cos_theta = 1.0 - u.x; break;
  }
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)), phi = 2.0 * kPiD * u.y;
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

double chi_square_p(const std::vector<glm::dvec2>& coordinates, double level, bool* passed,
                    const std::function<double(double u, double v)>& density) {
  constexpr int kGrid = 16;
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

std::optional<SamplerModel> fit_sampler(const std::vector<glm::dvec3>& half_vectors, double alpha) {
  std::vector<glm::dvec2> coordinates;
  coordinates.reserve(half_vectors.size());
  for (const SamplerModel& mistake : sampler_mistakes()) {
    coordinates.clear();
    for (const glm::dvec3& h : half_vectors) coordinates.push_back(sampler_coordinates(mistake, h, alpha));
    bool fits = false;
    (void)chi_square_p(coordinates, kMistakeLevel, &fits);
    if (fits) return mistake;
  }
  return std::nullopt;
}

}  // namespace raylab::grading::microfacet
