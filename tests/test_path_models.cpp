// Stage 09's furnaces against its modelled mistakes (autograder/suites/path_models.h), in plain
// arithmetic: every mistake moves some furnace far from the correct value, and no two mistakes
// made together cancel in a furnace that either of them alone moves, so that a submission with
// both passes none of the furnace tests that one of them fails (issue: "mistakes made together
// are named together"). The one pair left out is not a mistake: emission counted at every vertex
// with no direct light is path tracing without next-event estimation, which is unbiased.
//   Likewise stage 08's estimator tests against the estimator's modelled mistakes
// (autograder/suites/direct_models.h): DirectModels.
#include "direct_models.h"
#include "path_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace raylab::grading {
namespace {

// What a furnace test surely tells apart: without roulette the furnace has almost no noise and its
// t-test forgives 0.1% (kFurnaceTolerance), so 0.2% is far outside it; with roulette the pixel
// means spread by a few per cent, so 5%.
double detectable(const Furnace& furnace) { return furnace.roulette < 1.0 ? 0.05 : 0.002; }

double deviation(const std::vector<const PathMistake*>& made, const Furnace& furnace) {
  const double correct = furnace_value(correct_path_model(), furnace);
  return std::fabs(furnace_value(path_model_with(made), furnace) / correct - 1.0);
}

std::string name_of(const PathMistake& mistake) { return std::string("'") + mistake.name + "'"; }

bool is_path_tracing_without_light_sampling(const PathMistake& a, const PathMistake& b) {
  const auto is = [&](MessageId x, MessageId y) { return a.hint == x && b.hint == y; };
  return is(MessageId::path_emission_twice, MessageId::path_no_direct_light) ||
         is(MessageId::path_no_direct_light, MessageId::path_emission_twice);
}

TEST(PathModels, EveryMistakeFailsAFurnace) {
  for (const PathMistake& mistake : path_mistakes()) {
    double largest = 0.0;
    bool detected = false;
    for (const Furnace& furnace : kFurnaces) {
      largest = std::max(largest, deviation({&mistake}, furnace));
      detected = detected || deviation({&mistake}, furnace) >= detectable(furnace);
    }
    EXPECT_TRUE(detected) << "mistake " << name_of(mistake) << " moves no furnace detectably (at most "
                          << largest << ")";
  }
}

TEST(PathModels, NoTwoMistakesCancelInAFurnace) {
  const std::vector<PathMistake>& all = path_mistakes();
  int pairs = 0;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      if (is_path_tracing_without_light_sampling(all[i], all[j])) continue;
      ++pairs;
      for (int f = 0; f < kFurnaceCount; ++f) {
        const Furnace& furnace = kFurnaces[f];
        const double alone = std::max(deviation({&all[i]}, furnace), deviation({&all[j]}, furnace));
        if (alone < detectable(furnace)) continue;  // neither fails this furnace on its own
        EXPECT_GE(deviation({&all[i], &all[j]}, furnace), detectable(furnace))
            << "mistakes " << name_of(all[i]) << " and " << name_of(all[j]) << " cancel in furnace " << f
            << " (albedo " << furnace.albedo << ", roulette " << furnace.roulette << "): each alone moves it by "
            << alone << ", both together by " << deviation({&all[i], &all[j]}, furnace);
      }
    }
  EXPECT_EQ(pairs, 27);  // 8 mistakes: 28 pairs, one of them not a mistake
}

// A hint names a pair only when exactly one pair fits (09_path_test.cpp): every pair must differ
// from every other pair, and from every single mistake, in some furnace. But a pair that one of
// its mistakes masks (no direct light hides every mistake of the bounce weights: each pixel is the
// emission the camera sees) is that mistake alone in every furnace; its hint names that one.
bool apart(const std::vector<const PathMistake*>& a, const std::vector<const PathMistake*>& b) {
  for (const Furnace& furnace : kFurnaces)
    if (std::fabs(furnace_value(path_model_with(a), furnace) / furnace_value(path_model_with(b), furnace) - 1.0) >=
        detectable(furnace))
      return true;
  return false;
}

std::string names_of(const std::vector<const PathMistake*>& made) {
  std::string names;
  for (const PathMistake* mistake : made) names += (names.empty() ? "" : " + ") + name_of(*mistake);
  return names;
}

TEST(PathModels, EveryPairDiffersFromEveryOtherModel) {
  const std::vector<PathMistake>& all = path_mistakes();
  std::vector<std::vector<const PathMistake*>> models;
  for (const PathMistake& mistake : all) models.push_back({&mistake});
  int masked = 0;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      if (is_path_tracing_without_light_sampling(all[i], all[j])) continue;
      if (!apart({&all[i], &all[j]}, {&all[i]}) || !apart({&all[i], &all[j]}, {&all[j]})) {
        ++masked;
        continue;
      }
      models.push_back({&all[i], &all[j]});
    }
  for (std::size_t m = 0; m < models.size(); ++m)
    for (std::size_t n = m + 1; n < models.size(); ++n) {
      if (models[m].size() < 2 && models[n].size() < 2) continue;  // two single mistakes: the first test
      EXPECT_TRUE(apart(models[m], models[n]))
          << "the models " << names_of(models[m]) << " and " << names_of(models[n]) << " agree in every furnace";
    }
  EXPECT_LE(masked, 5);  // no direct light with each of the 5 mistakes of the bounce weight and depth
}

// ---- Stage 08: the one-sample estimator -----------------------------------------------------

// The estimator's models in a test with `lights` lights: each mistake alone, and each pair made
// together (the product of their factors), with their names.
struct DirectModel {
  std::string names;
  double factor;
};
std::vector<DirectModel> direct_models(int lights) {
  const std::vector<DirectMistake>& all = direct_mistakes();
  std::vector<DirectModel> models;
  for (const DirectMistake& mistake : all) models.push_back({mistake.name, mistake.factor(lights)});
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      models.push_back({std::string(all[i].name) + " + " + all[j].name, all[i].factor(lights) * all[j].factor(lights)});
  return models;
}

// What an estimator test surely tells apart: its mean tests have standard errors of about 1% of
// the mean (20,000 samples), so 20% is far outside them.
constexpr double kDirectDetectable = 0.2;

// The models that an estimator test with `lights` lights cannot tell from the right answer.
std::vector<std::string> direct_models_near_right(int lights) {
  std::vector<std::string> near;
  for (const DirectModel& model : direct_models(lights))
    if (!(std::fabs(model.factor - 1.0) >= kDirectDetectable)) near.push_back(model.names);
  return near;
}

TEST(DirectModels, EveryMistakeAndPairFailsEveryEstimatorTest) {
  // So no pair passes an estimator test that either of its mistakes fails.
  for (const int lights : kDirectEstimatorLights)
    for (const std::string& names : direct_models_near_right(lights))
      ADD_FAILURE() << "with " << lights << " lights, '" << names << "' is within " << kDirectDetectable
                    << " of the right answer";
  // The check itself: with three lights, the choice not divided by and 1 / pi missing give
  // pi / 3 = 1.047 (why EstimatorSeveralLights has four).
  EXPECT_EQ(direct_models_near_right(3).size(), 1u);
}

TEST(DirectModels, EveryModelDiffersFromEveryOtherInEachEstimatorTest) {
  // So the fit names one model, whichever test fails.
  for (const int lights : kDirectEstimatorLights) {
    const std::vector<DirectModel> models = direct_models(lights);
    for (std::size_t m = 0; m < models.size(); ++m)
      for (std::size_t n = m + 1; n < models.size(); ++n)
        EXPECT_GE(std::fabs(models[m].factor / models[n].factor - 1.0), kDirectDetectable)
            << "with " << lights << " lights, '" << models[m].names << "' and '" << models[n].names << "' agree";
  }
}

}  // namespace
}  // namespace raylab::grading
