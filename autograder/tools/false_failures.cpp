// Measures how often a Monte Carlo stage's graded tests fail the reference solution by bad luck.
// It runs the stage's own suite, in this process against the reference solutions (linked as in
// autograder-regenerate), round after round with other seeds (test_seed() in support.h), and
// counts the rounds in which any test failed. Each stage is designed to fail a correct program
// at most testkit::kGraderFalseFailureRate (1 in 1,000) of the time.
//   autograder-false-failures --stage 08_direct_light --rounds 1000
// (stages 08_direct_light, 09_path, 09b_mis and 10_microfacet.)
// For stage 09, autograder-path-false-failures also shows the tails of its region z-scores.
#include "grading.h"
#include "gtest_flags.h"
#include "support.h"

#include "raylab/testkit/statistics.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>

namespace {

using namespace raylab::grading;

// Seeds each round, and counts failed tests per name and rounds with a failure.
class RoundCounter : public ::testing::EmptyTestEventListener {
 public:
  void OnTestIterationStart(const ::testing::UnitTest&, int iteration) override {
    set_test_seed_round(static_cast<std::uint64_t>(iteration) + 1);  // round 0 is the graded seeds
    failed_this_round_ = false;
  }
  void OnTestEnd(const ::testing::TestInfo& test) override {
    if (!test.result()->Failed()) return;
    ++failures_[std::string(test.test_suite_name()) + "." + test.name()];
    failed_this_round_ = true;
  }
  void OnTestIterationEnd(const ::testing::UnitTest&, int iteration) override {
    rounds_failed_ += failed_this_round_ ? 1 : 0;
    std::fprintf(stderr, "\rround %d: %d rounds failed so far", iteration + 1, rounds_failed_);
  }
  int rounds_failed() const { return rounds_failed_; }
  const std::map<std::string, int>& failures() const { return failures_; }

 private:
  bool failed_this_round_ = false;
  int rounds_failed_ = 0;
  std::map<std::string, int> failures_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Measure a Monte Carlo stage's false failures on the reference solution"};
  std::string stage_name;
  int rounds = 100;
  app.add_option("--stage", stage_name, "The stage (08_direct_light, 09_path, 09b_mis or 10_microfacet)")->required();
  app.add_option("--rounds", rounds, "How many gradings, each with other seeds")->check(CLI::Range(1, 1000000));
  CLI11_PARSE(app, argc, argv);
  const StageInfo* stage = find_stage(stage_name);
  if (!stage || (stage->id != "08_direct_light" && stage->id != "09_path" && stage->id != "09b_mis" &&
                 stage->id != "10_microfacet")) {
    std::fprintf(stderr,
                 "autograder-false-failures: %s: only 08_direct_light, 09_path, 09b_mis and 10_microfacet draw every "
                 "seed through "
                 "test_seed() (support.h); the other stages' tests are exact or, for 07_sampling, measured "
                 "on the statistics module (docs/instructors.md)\n",
                 stage_name.c_str());
    return 2;
  }
  std::string filter;
  for (const TestInfo& test : tests())
    if (test.stage == stage->number) filter += (filter.empty() ? "" : ":") + test.full_name();

  int gtest_argc = 1;
  ::testing::InitGoogleTest(&gtest_argc, argv);
  GTEST_FLAG_SET(filter, filter);
  GTEST_FLAG_SET(repeat, rounds);
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  delete listeners.Release(listeners.default_result_printer());  // only the counts below
  auto* counter = new RoundCounter;
  listeners.Append(counter);
  const bool every_round_passed = RUN_ALL_TESTS() == 0;

  std::fprintf(stderr, "\n");
  const double rate = raylab::testkit::kGraderFalseFailureRate;
  std::printf("%s: %d gradings of the reference with other seeds, %d failed (designed for at most %.4g per grading: "
              "%.3g expected)\n",
              stage->id.c_str(), rounds, counter->rounds_failed(), rate, rate * rounds);
  if (every_round_passed != (counter->rounds_failed() == 0))
    std::printf("  (GoogleTest's own verdict disagrees with the count: %s)\n", every_round_passed ? "passed" : "failed");
  for (const auto& [name, count] : counter->failures()) std::printf("  %s failed %d times\n", name.c_str(), count);
  return 0;
}
