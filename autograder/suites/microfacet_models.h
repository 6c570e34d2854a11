// Stage 10's exact formulas and the fitted models of its mistakes (10_microfacet_test.cpp): each
// function's model is a product of parts (which distribution, which alpha, whether 1 / pi, the
// masking, the Fresnel cosine, the factor 4, the Jacobian), so that two or three mistakes made in
// one function are one member of its family. A fit returns the member, fewest changed parts first,
// that reproduces every value the student returned above the surface (0 below is a rule of its
// own). tests/test_microfacet_models.cpp proves that every member of every family is the one its
// own values fit, but where two members give the same values: f on your G1 without masking is f
// without masking (named as your G1), and f on your G1 of half the value with the 4 missing is f
// with the right masking (1/2 x 1/2 x 4 = 1). And that the samplers' mistakes, alone and in pairs,
// are each named by their own samples.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace raylab::grading::microfacet {

constexpr double kPiD = 3.14159265358979323846;
constexpr std::uint64_t kStageSeed = 10;  // the stage's seed (its cases and, mixed by round, its samples)

// ---- The exact formulas, in double, with the parts a mistake may change ------------------

enum class AlphaUse { AsIs, SquaredFirst, SquareRoot };  // alpha, alpha^2 or sqrt(alpha) in its place
double alpha_used(double alpha, AlphaUse use);
double ggx_d(double cos_h, double alpha);
double beckmann_d(double cos_h, double alpha);
double smith_g1(double cos_v, double alpha, bool tan_squared = true);
glm::dvec3 half_vector_of(const glm::vec3& wo, const glm::vec3& wi);
double schlick(double specular, double cosine);
// A unit vector at angle theta from the normal (cos_theta), azimuth phi.
glm::vec3 direction(float cos_theta, float phi);

// Whether a value matches (float tolerances: 2e-4 for the right answer, 1e-3 for a model).
bool close(double got, double expected, double relative = 2e-4);
bool close(const glm::vec3& got, const glm::dvec3& expected, double relative = 2e-4);

// The alphas and cosines the value tests ask at (cosines 0 and below included: 0 there).
extern const float kAlphas[3];
extern const float kCosines[8];

// A value of a function of one direction and alpha (D, G1, the half vectors' pdf), with the
// student's D at the same direction where a model is built on it.
struct ValueCase {
  glm::vec3 vector;
  float alpha;
  float got;
  float students_d = 0.0f;
};
// The cases at every alpha of kAlphas and cosine of kCosines, at azimuth phi, with `function`'s
// values.
std::vector<ValueCase> value_cases(float phi, const std::function<float(const glm::vec3&, float)>& function);

// ---- D -------------------------------------------------------------------------------------

struct DistributionModel {
  bool beckmann = false;
  AlphaUse alpha = AlphaUse::AsIs;
  bool no_inverse_pi = false;
  int changes() const { return int(beckmann) + int(alpha != AlphaUse::AsIs) + int(no_inverse_pi); }
  bool operator==(const DistributionModel& o) const {
    return beckmann == o.beckmann && alpha == o.alpha && no_inverse_pi == o.no_inverse_pi;
  }
};
std::vector<DistributionModel> distribution_models();  // the family, exact first, fewest changes first
double distribution_value(const DistributionModel& model, double cos_h, double alpha);
std::optional<DistributionModel> fit_distribution(const std::vector<ValueCase>& cases);  // never the exact one

// ---- G1 ------------------------------------------------------------------------------------

struct SmithG1Model {
  bool no_masking = false;  // 1 everywhere above the surface (the other parts do not apply)
  bool half = false;        // the numerator 1, not 2
  bool tan_not_squared = false;
  AlphaUse alpha = AlphaUse::AsIs;
  int changes() const { return int(no_masking) + int(half) + int(tan_not_squared) + int(alpha != AlphaUse::AsIs); }
  bool operator==(const SmithG1Model& o) const {
    return no_masking == o.no_masking && half == o.half && tan_not_squared == o.tan_not_squared && alpha == o.alpha;
  }
};
std::vector<SmithG1Model> smith_g1_models();
double smith_g1_value(const SmithG1Model& model, double cos_v, double alpha);
std::optional<SmithG1Model> fit_smith_g1(const std::vector<ValueCase>& cases);

// ---- f -------------------------------------------------------------------------------------

struct FCase {
  glm::vec3 wo, wi;
  float alpha;
  glm::vec3 specular;
  glm::vec3 got;
  // The student's own D(h) and G1(wo) G1(wi), for the models built on them.
  double students_d = 0.0, students_g = 0.0;
};
std::vector<FCase> f_cases();  // without values; the same in every grading (kStageSeed)
glm::dvec3 exact_f(const FCase& k);

enum class Masking { Exact, Students, None };
enum class FresnelAt { HalfVector, Normal, NoAngle, None };
struct FModel {
  bool students_d = false;
  Masking masking = Masking::Exact;
  FresnelAt fresnel = FresnelAt::HalfVector;
  bool four_missing = false;
  int changes() const { return int(masking == Masking::None) + int(fresnel != FresnelAt::HalfVector) + int(four_missing); }
  bool operator==(const FModel& o) const {
    return students_d == o.students_d && masking == o.masking && fresnel == o.fresnel && four_missing == o.four_missing;
  }
};
// The family, given whether the student's D and G1 are wrong (only then are models built on them).
std::vector<FModel> f_models(bool own_d, bool own_g);
glm::dvec3 f_value(const FModel& model, const FCase& k);  // above the surface
std::optional<FModel> fit_f(const std::vector<FCase>& cases, bool own_d, bool own_g);

// ---- The half vectors' density -----------------------------------------------------------

struct HalfVectorPdfModel {
  bool students_d = false;
  bool no_cosine = false;
  bool operator==(const HalfVectorPdfModel& o) const { return students_d == o.students_d && no_cosine == o.no_cosine; }
};
double half_vector_pdf_value(const HalfVectorPdfModel& model, const ValueCase& k);
std::optional<HalfVectorPdfModel> fit_half_vector_pdf(const std::vector<ValueCase>& cases, bool own_d);

// ---- wi's density ------------------------------------------------------------------------

enum class Jacobian { Right, Missing, AtNormal, FourMissing };
struct PdfCase {
  glm::vec3 wo, wi;
  float alpha;
  float got;
  double students_pdf_h = 0.0;  // the student's ggx_half_vector_pdf at the half vector
};
struct PdfModel {
  bool students_pdf_h = false;
  Jacobian jacobian = Jacobian::Right;
  bool operator==(const PdfModel& o) const { return students_pdf_h == o.students_pdf_h && jacobian == o.jacobian; }
};
double pdf_value(const PdfModel& model, const PdfCase& k);
std::optional<PdfModel> fit_pdf(const std::vector<PdfCase>& cases, bool own_pdf_h);

// ---- The samplers ----------------------------------------------------------------------------

// The coordinates in which half vectors of density D(h) cos(theta_h) (GGX of `alpha`) are uniform
// in [0, 1)^2: the share of that density within theta, tan^2 / (alpha^2 + tan^2), and phi / 2 pi.
glm::dvec2 ggx_uniform_coordinates(const glm::dvec3& h, double alpha);

// A mistaken half-vector sampler whose density is known: its shape (GGX's, tan without the square
// root, Beckmann's, cos(theta) uniform) with an alpha used as it is, squared or square-rooted.
enum class SamplerShape { Ggx, NoSquareRoot, Beckmann, UniformCosine };
struct SamplerModel {
  SamplerShape shape = SamplerShape::Ggx;
  AlphaUse alpha = AlphaUse::AsIs;
  bool operator==(const SamplerModel& o) const { return shape == o.shape && alpha == o.alpha; }
};
// The mistakes the fit knows, one changed part first, then the pairs.
std::vector<SamplerModel> sampler_mistakes();
// The coordinates that are uniform in [0, 1)^2 when the half vectors follow `model`.
glm::dvec2 sampler_coordinates(const SamplerModel& model, const glm::dvec3& h, double alpha);
// A half vector sampled as `model` samples it from u in [0, 1)^2.
glm::dvec3 sample_with(const SamplerModel& model, const glm::dvec2& u, double alpha);

// The chi-square test of coordinates in [0, 1)^2 on the 16 x 16 grid against `density` there
// (uniform when none is given) at `level`: its p-value, and whether it passed.
double chi_square_p(const std::vector<glm::dvec2>& coordinates, double level, bool* passed,
                    const std::function<double(double u, double v)>& density = nullptr);

constexpr double kMistakeLevel = 1e-6;  // a mistake's density "fits" the samples above this p
// The first mistake whose density fits the half vectors, or none.
std::optional<SamplerModel> fit_sampler(const std::vector<glm::dvec3>& half_vectors, double alpha);

}  // namespace raylab::grading::microfacet
