// Stage 09b's scripted tests against their modelled mistakes (autograder/suites/mis_models.h):
// every mistake is named alone by the fit of a test it fails; every pair fails each test that
// either of its mistakes fails, and the fit there names both, or, where the pair's values are
// those of one of them alone, that one (issue: "mistakes made together are named together"). The values of a model are what a path tracer making those mistakes returns; the
// reference path tracer's are the correct model's.
#include "mis_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace raylab::grading::mis {
namespace {

// The scripted tests of 09b_mis_test.cpp (mis_models.h), each with its paths and their parts.
struct ScriptedTestParts {
  std::string name;
  MisScene scene;
  std::vector<MisScriptedPath> paths;
  std::vector<PathParts> parts;
};
std::vector<ScriptedTestParts> tests_with_parts() {
  std::vector<ScriptedTestParts> tests;
  for (const ScriptedTest& test : scripted_tests()) {
    const std::vector<MisScriptedPath> paths = scripted_paths(test.max_depth);
    tests.push_back({test.test, test.scene, paths, parts_of(test.scene, paths)});
  }
  return tests;
}

// A path tracer with a model's mistakes: the values it returns. A mistake that can be made in
// more than one way (model_values) gives one path tracer per way, each taking the same way on
// every path (the k-th value, or the last where a path has fewer).
std::vector<std::vector<glm::vec3>> returned_values(const ScriptedTestParts& test, const MisModel& model) {
  std::vector<std::vector<glm::dvec3>> values;
  std::size_t ways = 1;
  for (const PathParts& p : test.parts) {
    values.push_back(model_values(p, model));
    ways = std::max(ways, values.back().size());
  }
  std::vector<std::vector<glm::vec3>> tracers(ways);
  for (std::size_t k = 0; k < ways; ++k)
    for (const std::vector<glm::dvec3>& path : values) tracers[k].push_back(glm::vec3(path[std::min(k, path.size() - 1)]));
  return tracers;
}

bool all_right(const ScriptedTestParts& test, const std::vector<glm::vec3>& got) {
  return fits(got, test.parts, MisModel{});
}

// Whether a mistake alone fails the test, whichever way it is made.
bool fails(const ScriptedTestParts& test, const MisModel& model) {
  for (const std::vector<glm::vec3>& got : returned_values(test, model))
    if (all_right(test, got)) return false;
  return true;
}

std::string names(const MisFit& fit) {
  std::string text;
  for (const MisMistake* m : fit.named) text += (text.empty() ? "'" : " + '") + std::string(m->name) + "'";
  return text.empty() ? "nothing" : text;
}

TEST(MisModels, TheReferencePathTracerIsTheCorrectModel) {
  for (const ScriptedTestParts& test : tests_with_parts()) {
    const std::vector<glm::vec3> got = mis_scripted_paths(test.scene, test.paths);
    EXPECT_TRUE(all_right(test, got)) << test.name;
  }
}

TEST(MisModels, EveryMistakeFailsATestThatNamesItAlone) {
  const std::vector<ScriptedTestParts> tests = tests_with_parts();
  for (const MisMistake& mistake : mis_mistakes()) {
    int failed = 0;
    for (const ScriptedTestParts& test : tests) {
      if (!fails(test, mistake.model)) continue;
      ++failed;
      for (const std::vector<glm::vec3>& got : returned_values(test, mistake.model)) {
        const MisFit fit = fit_mistakes(got, test.parts);
        EXPECT_TRUE(fit.named.size() == 1 && fit.named[0] == &mistake)
            << "'" << mistake.name << "' fails " << test.name << ", whose fit names " << names(fit);
      }
    }
    EXPECT_GE(failed, 1) << "'" << mistake.name << "' fails no scripted test";
  }
}

// Whether the values are those of `model` made alone, in one of its ways.
bool same_as(const ScriptedTestParts& test, const std::vector<glm::vec3>& got, const MisModel& model) {
  for (const std::vector<glm::vec3>& alone : returned_values(test, model))
    if (alone == got) return true;
  return false;
}

// For each pair and each test that either of its mistakes fails: the pair fails it too (they do
// not cancel), and the fit names both. Where the values are those of one of them alone (no MIS
// leaves no weight to get wrong; nor does the emission counted with weight 1 on both sides, the
// light sample's way of that mistake) that one is named; never a mistake not made.
TEST(MisModels, EveryPairFailsAndIsNamed) {
  const std::vector<ScriptedTestParts> tests = tests_with_parts();
  const std::vector<MisMistake>& all = mis_mistakes();
  int named_together = 0;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      const MisModel pair = both(all[i].model, all[j].model);
      const std::string pair_name = std::string("'") + all[i].name + "' + '" + all[j].name + "'";
      for (const ScriptedTestParts& test : tests) {
        const bool fails_i = fails(test, all[i].model), fails_j = fails(test, all[j].model);
        if (!fails_i && !fails_j) continue;
        for (const std::vector<glm::vec3>& got : returned_values(test, pair)) {
          const MisFit fit = fit_mistakes(got, test.parts);
          const bool as_i = same_as(test, got, all[i].model), as_j = same_as(test, got, all[j].model);
          if (as_i || as_j) {
            // One mistake's values: the fit names that one, when it shows here.
            const MisMistake& shown = as_i ? all[i] : all[j];
            if (fails(test, shown.model)) {
              EXPECT_TRUE(fit.named.size() == 1 && fit.named[0] == &shown)
                  << pair_name << " in " << test.name << " (the values of '" << shown.name << "'): the fit names "
                  << names(fit);
            }
            const bool hides_weights = shown.hint == MessageId::mis_no_mis || shown.hint == MessageId::mis_emission_twice;
            if ((as_i ? fails_j : fails_i) && !(as_i && as_j)) {
              EXPECT_TRUE(hides_weights) << pair_name << " in " << test.name << " give the values of '" << shown.name
                                         << "' alone, which fail this test less";
            }
            continue;
          }
          if (all_right(test, got)) {
            ADD_FAILURE() << pair_name << " pass " << test.name << ", which one of them alone fails";
            continue;
          }
          EXPECT_TRUE(fit.together && fit.named.size() == 2 &&
                      fit.named[0] == &all[i] && fit.named[1] == &all[j])
              << pair_name << " in " << test.name << ": the fit names " << names(fit);
          ++named_together;
        }
      }
    }
  // The balance heuristic with each of the other four weighting mistakes, each in the test that
  // shows both (with an area density in the weight in its two ways), and an area density with the
  // emission unweighted. The other pairs' mistakes show in different tests, each named there.
  EXPECT_EQ(named_together, 6);
}

}  // namespace
}  // namespace raylab::grading::mis
