// Stage 10's fitted models (autograder/suites/microfacet_models.h) against themselves, in plain
// arithmetic: every member of each function's family (every single mistake, every pair and every
// triple its parts make) is the member the fit names for that member's own values, so that two
// mistakes made in one function get both their hints. Where a model is built on the student's own
// wrong D, G1 or half-vector density, each of their modelled mistakes stands in for it. And the
// half-vector samplers' mistakes, alone and in pairs (a shape with an alpha), each fail the
// chi-square test against GGX and are named by their own samples (issue: "mistakes made together
// are named together").
#include "microfacet_models.h"

#include "raylab/random.h"
#include "raylab/testkit/statistics.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace raylab::grading::microfacet {
namespace {

std::string describe(const DistributionModel& m) {
  return std::string(m.beckmann ? "Beckmann" : "GGX") + ", alpha " + std::to_string(int(m.alpha)) +
         (m.no_inverse_pi ? ", no 1 / pi" : "");
}
std::string describe(const SmithG1Model& m) {
  if (m.no_masking) return "no masking";
  return std::string(m.half ? "half, " : "") + (m.tan_not_squared ? "tan not squared, " : "") + "alpha " +
         std::to_string(int(m.alpha));
}
std::string describe(const FModel& m) {
  return std::string(m.students_d ? "your D, " : "") + "masking " + std::to_string(int(m.masking)) + ", Fresnel " +
         std::to_string(int(m.fresnel)) + (m.four_missing ? ", no 4" : "");
}

TEST(MicrofacetModels, EveryDistributionModelIsTheOneItsValuesFit) {
  int fitted = 0;
  for (const DistributionModel& m : distribution_models()) {
    if (m.changes() == 0) continue;
    const std::vector<ValueCase> cases = value_cases(
        0.7f, [&](const glm::vec3& v, float alpha) { return static_cast<float>(distribution_value(m, v.z, alpha)); });
    const std::optional<DistributionModel> fit = fit_distribution(cases);
    EXPECT_TRUE(fit && *fit == m) << describe(m) << " is fitted as " << (fit ? describe(*fit) : "nothing");
    ++fitted;
  }
  EXPECT_EQ(fitted, 11);  // 2 distributions x 3 alphas x 2: 12, less the exact one
}

TEST(MicrofacetModels, EverySmithG1ModelIsTheOneItsValuesFit) {
  int fitted = 0;
  for (const SmithG1Model& m : smith_g1_models()) {
    if (m.changes() == 0) continue;
    const std::vector<ValueCase> cases = value_cases(
        2.1f, [&](const glm::vec3& v, float alpha) { return static_cast<float>(smith_g1_value(m, v.z, alpha)); });
    const std::optional<SmithG1Model> fit = fit_smith_g1(cases);
    EXPECT_TRUE(fit && *fit == m) << describe(m) << " is fitted as " << (fit ? describe(*fit) : "nothing");
    ++fitted;
  }
  EXPECT_EQ(fitted, 12);  // no masking, and half x tan x 3 alphas: 1 + 2 x 2 x 3 = 13, less the exact one
}

// f with each of its models, on each wrong D and wrong G1 the student may have beside it (the
// exact ones included: then no model is built on them).
TEST(MicrofacetModels, EveryFModelIsTheOneItsValuesFit) {
  std::vector<DistributionModel> ds = distribution_models();  // exact first
  std::vector<SmithG1Model> gs = smith_g1_models();
  int fitted = 0, cancelling = 0;
  for (const DistributionModel& d : ds)
    for (const SmithG1Model& g : gs) {
      const bool own_d = d.changes() > 0, own_g = g.changes() > 0;
      std::vector<FCase> cases = f_cases();
      for (FCase& k : cases) {
        if (!(k.wo.z > 0.0f && k.wi.z > 0.0f)) continue;
        const glm::dvec3 h = half_vector_of(k.wo, k.wi);
        k.students_d = static_cast<float>(distribution_value(d, glm::vec3(h).z, k.alpha));
        k.students_g = double(static_cast<float>(smith_g1_value(g, k.wo.z, k.alpha))) *
                       static_cast<float>(smith_g1_value(g, k.wi.z, k.alpha));
      }
      for (const FModel& m : f_models(own_d, own_g)) {
        if (m == FModel{}) continue;
        // Your G1 without masking is masking None: the two are one model, named as your G1.
        if (m.masking == Masking::None && own_g && g.no_masking) continue;
        // Your G1 halved, used twice and the 4 missing: 1/2 x 1/2 x 4 = 1, the values of the model
        // with the exact masking and the 4 (with nothing else changed, f is right and passes;
        // SmithG1 charges the G1). No value tells them apart.
        if (m.masking == Masking::Students && m.four_missing && g == SmithG1Model{false, true, false, AlphaUse::AsIs}) {
          ++cancelling;
          continue;
        }
        for (FCase& k : cases)
          k.got = (k.wo.z > 0.0f && k.wi.z > 0.0f) ? glm::vec3(f_value(m, k)) : glm::vec3(0.0f);
        const std::optional<FModel> fit = fit_f(cases, own_d, own_g);
        EXPECT_TRUE(fit && *fit == m) << describe(m) << " beside D " << describe(d) << " and G1 " << describe(g)
                                      << " is fitted as " << (fit ? describe(*fit) : "nothing");
        ++fitted;
      }
    }
  EXPECT_GT(fitted, 5000);
  EXPECT_EQ(cancelling, 4 + 11 * 8);  // 4 Fresnel models beside the exact D; beside each wrong D, x your D or not
}

TEST(MicrofacetModels, EveryHalfVectorPdfModelIsTheOneItsValuesFit) {
  int fitted = 0;
  for (const DistributionModel& d : distribution_models()) {
    const bool own_d = d.changes() > 0;
    for (const bool students_d : {false, true})
      for (const bool no_cosine : {false, true}) {
        const HalfVectorPdfModel m{students_d, no_cosine};
        if ((students_d && !own_d) || m == HalfVectorPdfModel{}) continue;
        std::vector<ValueCase> cases = value_cases(1.3f, [](const glm::vec3&, float) { return 0.0f; });
        for (ValueCase& k : cases) {
          k.students_d = static_cast<float>(distribution_value(d, k.vector.z, k.alpha));
          k.got = static_cast<float>(half_vector_pdf_value(m, k));
        }
        const std::optional<HalfVectorPdfModel> fit = fit_half_vector_pdf(cases, own_d);
        EXPECT_TRUE(fit && *fit == m) << "your D " << students_d << ", no cosine " << no_cosine << " beside D "
                                      << describe(d) << " is fitted as "
                                      << (fit ? std::to_string(fit->students_d) + std::to_string(fit->no_cosine) : "nothing");
        ++fitted;
      }
  }
  EXPECT_EQ(fitted, 1 + 11 * 3);  // no cosine beside the exact D; beside each wrong D, also yours with and without
}

TEST(MicrofacetModels, EveryPdfModelIsTheOneItsValuesFit) {
  // The student's half-vector density: exact, or each of its models on each D.
  struct Density {
    DistributionModel d;
    HalfVectorPdfModel model;
  };
  std::vector<Density> densities;
  for (const DistributionModel& d : distribution_models())
    for (const bool no_cosine : {false, true}) densities.push_back({d, {d.changes() > 0, no_cosine}});
  int fitted = 0;
  for (const Density& density : densities) {
    const bool own = density.d.changes() > 0 || density.model.no_cosine;
    for (const Jacobian jacobian : {Jacobian::Right, Jacobian::Missing, Jacobian::AtNormal, Jacobian::FourMissing})
      for (const bool students : {false, true}) {
        const PdfModel m{students, jacobian};
        if ((students && !own) || m == PdfModel{}) continue;
        std::vector<PdfCase> cases;
        for (const FCase& k : f_cases()) {
          PdfCase c{k.wo, k.wi, k.alpha, 0.0f};
          if (k.wo.z > 0.0f && k.wi.z > 0.0f) {
            const glm::vec3 h(half_vector_of(k.wo, k.wi));
            ValueCase at_h{h, k.alpha, 0.0f, static_cast<float>(distribution_value(density.d, h.z, k.alpha))};
            c.students_pdf_h = static_cast<float>(half_vector_pdf_value(density.model, at_h));
          }
          c.got = static_cast<float>(pdf_value(m, c));
          cases.push_back(c);
        }
        const std::optional<PdfModel> fit = fit_pdf(cases, own);
        EXPECT_TRUE(fit && *fit == m) << "your pdf_h " << students << ", Jacobian " << int(jacobian) << " beside D "
                                      << describe(density.d) << " is fitted as "
                                      << (fit ? std::to_string(fit->students_pdf_h) + "/" + std::to_string(int(fit->jacobian))
                                              : "nothing");
        ++fitted;
      }
  }
  EXPECT_GT(fitted, 100);
}

// Each mistaken sampler's own 100,000 half vectors (as the stage's test draws) at the two alphas
// of HalfVectorSamples: they fail GGX's chi-square test at the stage's level, and the fit names
// that mistake, not another.
TEST(MicrofacetModels, EverySamplerMistakeAndPairIsNamedByItsSamples) {
  const double level = testkit::sidak_level(testkit::kGraderFalseFailureRate, 4);
  int index = 0;
  for (const SamplerModel& mistake : sampler_mistakes())
    for (const double alpha : {0.125, 0.5}) {
      Pcg32 random(10, static_cast<std::uint64_t>(++index));
      std::vector<glm::dvec3> half_vectors;
      std::vector<glm::dvec2> ggx;
      for (int i = 0; i < 100000; ++i) {
        const double u = random.next_float(), v = random.next_float();
        half_vectors.push_back(sample_with(mistake, {u, v}, alpha));
        ggx.push_back(ggx_uniform_coordinates(half_vectors.back(), alpha));
      }
      bool passed = true;
      (void)chi_square_p(ggx, level, &passed);
      EXPECT_FALSE(passed) << "shape " << int(mistake.shape) << ", alpha " << int(mistake.alpha) << " at alpha " << alpha
                           << " passes as GGX";
      const std::optional<SamplerModel> fit = fit_sampler(half_vectors, alpha);
      EXPECT_TRUE(fit && *fit == mistake) << "shape " << int(mistake.shape) << ", alpha " << int(mistake.alpha)
                                          << " at alpha " << alpha << " is fitted as "
                                          << (fit ? std::to_string(int(fit->shape)) + "/" + std::to_string(int(fit->alpha))
                                                  : "nothing");
    }
}

}  // namespace
}  // namespace raylab::grading::microfacet
