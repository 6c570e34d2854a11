// The kit's statistics module (testkit/statistics.h): its special functions against exact
// identities and published quantiles, its tests' power (they reject clearly wrong
// distributions and means) and their false-failure rates, measured over many seeds: a test
// designed for a rate r fails a correct input in about r of the runs, neither much more
// (a correct student would fail by bad luck) nor much less (it would be weaker than it says).
#include "raylab/random.h"
#include "raylab/testkit/random_values.h"
#include "raylab/testkit/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace raylab::testkit {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A uniform double in (0, 1) with 32 random bits (never 0, so logs are finite).
double uniform_open(Pcg32& random) { return (random.next_uint32() + 0.5) * (1.0 / 4294967296.0); }

// A standard normal value (Box-Muller; the second value is dropped to keep one draw pattern).
double normal_value(Pcg32& random) {
  const double radius = std::sqrt(-2.0 * std::log(uniform_open(random)));
  return radius * std::cos(2.0 * kPi * uniform_open(random));
}

// Failures of a test with false-failure rate `rate` over `runs` independent runs are
// Binomial(runs, rate). These bounds hold with probability 1 - 6e-7 (5 standard deviations)
// for a test whose rate is right, and exclude a rate 1.5 times too high or too low at 0.05
// (4000 runs) and twice too high at 0.001 (20 000 runs): a miscalibrated test is caught.
void expect_rate_near(int failures, int runs, double rate, const char* what) {
  const double mean = runs * rate, deviation = std::sqrt(runs * rate * (1.0 - rate));
  std::printf("  %s: %d false failures in %d runs, designed for %.0f (rate %.4g)\n", what, failures, runs, mean, rate);
  EXPECT_GE(failures, mean - 5.0 * deviation) << what << ": " << failures << " failures in " << runs
                                              << " runs, designed for " << mean << " (the test is too lenient)";
  EXPECT_LE(failures, mean + 5.0 * deviation) << what << ": " << failures << " failures in " << runs
                                              << " runs, designed for " << mean << " (false failures too often)";
}

// ---- Special functions ----------------------------------------------------------------------

TEST(Statistics, IncompleteGammaMatchesClosedFormsOnBothSidesOfItsSwitch) {
  for (const double x : {1e-6, 0.1, 0.5, 1.0, 2.0, 5.0, 20.0, 100.0}) {
    EXPECT_NEAR(regularized_gamma_p(1.0, x), -std::expm1(-x), 1e-14) << "x = " << x;
    EXPECT_NEAR(regularized_gamma_q(1.0, x) / std::exp(-x), 1.0, 1e-12) << "x = " << x;  // tail keeps its digits
    // Q(1/2, x) = erfc(sqrt(x)): the chi-square tail with one degree of freedom.
    EXPECT_NEAR(regularized_gamma_q(0.5, x) / std::erfc(std::sqrt(x)), 1.0, 1e-11) << "x = " << x;
    EXPECT_NEAR(regularized_gamma_p(3.5, x) + regularized_gamma_q(3.5, x), 1.0, 1e-14);
  }
}

TEST(Statistics, ChiSquareQuantilesMatchPublishedTables) {
  EXPECT_NEAR(chi_square_quantile(0.95, 1), 3.841458820694124, 1e-9);
  EXPECT_NEAR(chi_square_quantile(0.99, 10), 23.209251158954356, 1e-9);
  EXPECT_NEAR(chi_square_quantile(0.999, 100), 149.4493, 1e-3);
  EXPECT_NEAR(chi_square_cdf(chi_square_quantile(0.3, 7.0), 7.0), 0.3, 1e-12);
  EXPECT_NEAR(chi_square_upper_tail(3.841458820694124, 1), 0.05, 1e-12);
}

TEST(Statistics, IncompleteBetaMatchesClosedForms) {
  for (const double x : {0.001, 0.1, 0.3, 0.5, 0.7, 0.9, 0.999}) {
    EXPECT_NEAR(regularized_beta(1.0, 3.0, x), 1.0 - std::pow(1.0 - x, 3.0), 1e-13) << "x = " << x;
    EXPECT_NEAR(regularized_beta(2.5, 1.0, x), std::pow(x, 2.5), 1e-13) << "x = " << x;
    EXPECT_NEAR(regularized_beta(4.0, 7.0, x) + regularized_beta(7.0, 4.0, 1.0 - x), 1.0, 1e-13);
  }
  EXPECT_NEAR(regularized_beta(30.0, 30.0, 0.5), 0.5, 1e-13);
}

TEST(Statistics, StudentTMatchesClosedFormsAndTables) {
  for (const double t : {-30.0, -2.0, -0.5, 0.0, 0.7, 3.0, 50.0}) {
    EXPECT_NEAR(student_t_cdf(t, 1.0), 0.5 + std::atan(t) / kPi, 1e-13) << "t = " << t;  // Cauchy
    EXPECT_NEAR(student_t_cdf(t, 2.0), 0.5 + t / (2.0 * std::sqrt(2.0 + t * t)), 1e-13) << "t = " << t;
  }
  EXPECT_NEAR(student_t_quantile(0.975, 10), 2.228138851986, 1e-9);
  EXPECT_NEAR(student_t_quantile(0.995, 30), 2.749995653567, 1e-9);
  EXPECT_NEAR(student_t_quantile(1e-9, 5), -student_t_quantile(1.0 - 1e-9, 5), 1e-4);
  EXPECT_NEAR(student_t_cdf(2.0, 1e6), normal_cdf(2.0), 1e-6);  // t tends to the normal
}

TEST(Statistics, NormalQuantilesMatchPublishedValues) {
  EXPECT_NEAR(normal_quantile(0.975), 1.959963984540054, 1e-12);
  EXPECT_NEAR(normal_quantile(0.5), 0.0, 1e-14);
  EXPECT_NEAR(normal_quantile(1e-10), -6.361340902404056, 1e-9);
  EXPECT_NEAR(normal_quantile(1.0 - 1e-6), 4.753424308822899, 1e-7);
  EXPECT_THROW(normal_quantile(0.0), std::invalid_argument);
  EXPECT_THROW(normal_quantile(1.0), std::invalid_argument);
}

TEST(Statistics, BinomialTailMatchesTheDirectSum) {
  const int n = 20;
  const double p = 0.3;
  for (int k = 0; k <= n; ++k) {
    double direct = 0;
    for (int j = k; j <= n; ++j)
      direct += std::exp(std::lgamma(n + 1.0) - std::lgamma(j + 1.0) - std::lgamma(n - j + 1.0)) * std::pow(p, j) *
                std::pow(1.0 - p, n - j);
    EXPECT_NEAR(binomial_upper_tail(k, n, p), direct, 1e-12) << "k = " << k;
  }
}

TEST(Statistics, SidakLevelKeepsTheFamilyRate) {
  EXPECT_NEAR(sidak_level(0.01, 1), 0.01, 1e-15);
  const double level = sidak_level(kGraderFalseFailureRate, 10);
  EXPECT_NEAR(1.0 - std::pow(1.0 - level, 10), kGraderFalseFailureRate, 1e-15);
  EXPECT_GT(level, kGraderFalseFailureRate / 10);  // a little above Bonferroni's
  EXPECT_LT(level, kGraderFalseFailureRate / 10 * 1.001);
}

// ---- Chi-square ------------------------------------------------------------------------------

// density(u, v) = 2u on the unit square: the first columns expect few samples, so the test pools.
double linear_density(double u, double) { return 2.0 * u; }

Histogram2D linear_samples(Pcg32& random, int count, bool correct) {
  Histogram2D histogram(16, 4, 0.0, 1.0, 0.0, 1.0);
  for (int i = 0; i < count; ++i) {
    const double x = uniform_open(random), v = uniform_open(random);
    histogram.add(correct ? std::sqrt(x) : x, v);  // inversion of the CDF u^2; without the root, uniform
  }
  return histogram;
}

TEST(Statistics, ExpectedCountsIntegrateTheDensityOverEachCell) {
  const Histogram2D histogram(16, 4, 0.0, 1.0, 0.0, 1.0);
  const std::vector<double> expected = histogram.expected_counts(linear_density, 1000.0);
  double total = 0;
  for (double e : expected) total += e;
  EXPECT_NEAR(total, 1000.0, 1e-9);
  // Column c of a row: 1000 / 4 * ((c + 1)^2 - c^2) / 256.
  EXPECT_NEAR(expected[0], 1000.0 / 4.0 / 256.0, 1e-12);
  EXPECT_NEAR(expected[15], 1000.0 / 4.0 * 31.0 / 256.0, 1e-10);
}

TEST(Statistics, ChiSquareRejectsClearlyWrongDistributions) {
  Pcg32 random(1, stream_of("statistics"));
  const double level = 1e-4;
  {
    // Uniform samples tested against 2u (a square root missing in the inversion).
    const Histogram2D histogram = linear_samples(random, 2000, false);
    const ChiSquareResult result =
        chi_square_test(histogram.counts(), histogram.expected_counts(linear_density, 2000.0), level);
    EXPECT_FALSE(result.passed) << result.describe();
    EXPECT_LT(result.p_value, 1e-20) << result.describe();
  }
  {
    // Correct samples, against a density 10% too small everywhere (a pdf not normalised).
    const Histogram2D histogram = linear_samples(random, 100000, true);
    const ChiSquareResult result = chi_square_test(
        histogram.counts(), histogram.expected_counts([](double u, double) { return 1.8 * u; }, 100000.0), level);
    EXPECT_FALSE(result.passed) << result.describe();
    EXPECT_NEAR(result.expected_total / result.observed_total, 0.9, 1e-9);
  }
  {
    // Samples where the density is 0: rejected outright, with the reason.
    std::vector<double> observed = {50, 50, 3}, expected = {51.5, 51.5, 0};
    const ChiSquareResult result = chi_square_test(observed, expected, level);
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.samples_where_none_expected, 3);
    EXPECT_NE(result.reason.find("density is 0"), std::string::npos) << result.reason;
  }
  {
    // A small bias (5% more samples in one half) with enough samples to see it.
    Histogram2D histogram(8, 8, 0.0, 1.0, 0.0, 1.0);
    for (int i = 0; i < 200000; ++i) {
      double u = uniform_open(random);
      if (u > 0.5 && uniform_open(random) < 0.05) u -= 0.5;
      histogram.add(u, uniform_open(random));
    }
    const ChiSquareResult result =
        chi_square_test(histogram.counts(), histogram.expected_counts([](double, double) { return 1.0; }, 200000.0), level);
    EXPECT_FALSE(result.passed) << result.describe();
  }
}

// The grader words each failure itself, in English or Chinese, from `failure` (and `reason` in English).
TEST(Statistics, ChiSquareNamesWhyItFailed) {
  const double level = 1e-3;
  const ChiSquareResult fits = chi_square_test({100, 100, 100}, {100, 100, 100}, level);
  EXPECT_TRUE(fits.passed);
  EXPECT_EQ(fits.failure, ChiSquareFailure::none);
  EXPECT_EQ(fits.min_expected_count, 5.0);
  const ChiSquareResult misfit = chi_square_test({200, 50, 50}, {100, 100, 100}, level);
  EXPECT_EQ(misfit.failure, ChiSquareFailure::misfit) << misfit.reason;
  const ChiSquareResult where_none = chi_square_test({100, 100, 5}, {102.5, 102.5, 0}, level);
  EXPECT_EQ(where_none.failure, ChiSquareFailure::samples_where_none_expected) << where_none.reason;
  const ChiSquareResult too_few = chi_square_test({2, 1, 1}, {2, 1, 1}, level);
  EXPECT_EQ(too_few.failure, ChiSquareFailure::too_few_samples) << too_few.reason;
  const ChiSquareResult invalid = chi_square_test({1, 1}, {1, -1}, level);
  EXPECT_EQ(invalid.failure, ChiSquareFailure::invalid_expected) << invalid.reason;
  for (const ChiSquareResult& failed : {misfit, where_none, too_few, invalid}) {
    EXPECT_FALSE(failed.passed);
    EXPECT_FALSE(failed.reason.empty());
  }
}

TEST(Statistics, ChiSquarePoolsLowCountCellsAndPassesTheRightDistribution) {
  Pcg32 random(2, stream_of("statistics"));
  const Histogram2D histogram = linear_samples(random, 400, true);
  const ChiSquareResult result =
      chi_square_test(histogram.counts(), histogram.expected_counts(linear_density, 400.0), 1e-3);
  // 400 samples in 64 cells: the cells of the first columns expect fewer than 5 and are pooled.
  EXPECT_GT(result.pooled_cells, 8u) << result.describe();
  EXPECT_LT(result.degrees_of_freedom, 63) << result.describe();
  EXPECT_TRUE(result.passed) << result.describe();
}

TEST(Statistics, ChiSquareFalseFailureRateIsItsSignificanceLevel) {
  // Small samples (400 in 64 cells, many pooled) are where the chi-square approximation is
  // weakest; the rate must hold there too. 0.05 measures the calibration with many failures,
  // 0.001 is the grader's rate.
  for (const double level : {0.05, 0.001}) {
    const int runs = level > 0.01 ? 4000 : 20000;
    int failures = 0;
    for (int run = 0; run < runs; ++run) {
      Pcg32 random(static_cast<std::uint64_t>(run), stream_of("chi-square rate"));
      const Histogram2D histogram = linear_samples(random, 400, true);
      failures += !chi_square_test(histogram.counts(), histogram.expected_counts(linear_density, 400.0, 2), level).passed;
    }
    expect_rate_near(failures, runs, level, "chi-square");
  }
}

// ---- Means -------------------------------------------------------------------------------------

TEST(Statistics, RunningMomentsMatchTwoPassFormulasAndMerge) {
  Pcg32 random(3, stream_of("statistics"));
  std::vector<double> values;
  RunningMoments all, first, second;
  for (int i = 0; i < 1000; ++i) {
    const double value = 1e6 + normal_value(random);  // a large mean: no cancellation allowed
    values.push_back(value);
    all.add(value);
    (i < 300 ? first : second).add(value);
  }
  double mean = 0;
  for (double v : values) mean += v;
  mean /= values.size();
  double squares = 0;
  for (double v : values) squares += (v - mean) * (v - mean);
  EXPECT_NEAR(all.mean(), mean, 1e-8);
  EXPECT_NEAR(all.variance(), squares / 999.0, 1e-8);
  first.merge(second);
  EXPECT_EQ(first.count(), 1000u);
  EXPECT_NEAR(first.mean(), mean, 1e-8);
  EXPECT_NEAR(first.variance(), all.variance(), 1e-8);
}

TEST(Statistics, MeanTestRejectsAWrongMean) {
  Pcg32 random(4, stream_of("statistics"));
  std::vector<double> shifted, many;
  for (int i = 0; i < 100; ++i) shifted.push_back(0.5 + normal_value(random));
  const MeanTestResult t = mean_test(shifted, 0.0, 1e-3);
  EXPECT_FALSE(t.passed) << t.describe();
  EXPECT_EQ(t.degrees_of_freedom, 99.0);
  // Large samples use the normal distribution: 0.05 is 7 standard errors at 20 000 values.
  for (int i = 0; i < 20000; ++i) many.push_back(0.05 + normal_value(random));
  const MeanTestResult z = mean_test(many, 0.0, 1e-3);
  EXPECT_FALSE(z.passed) << z.describe();
  EXPECT_EQ(z.degrees_of_freedom, 0.0);
  EXPECT_TRUE(mean_test(many, 0.05, 1e-3).passed) << mean_test(many, 0.05, 1e-3).describe();
}

TEST(Statistics, MeanTestWithoutSpreadPassesOnlyTheExactValueOrWithinSlack) {
  const std::vector<double> constant(10, 0.25);
  EXPECT_TRUE(mean_test(constant, 0.25, 1e-3).passed);
  EXPECT_FALSE(mean_test(constant, 0.3, 1e-3).passed);
  EXPECT_TRUE(mean_test(constant, 0.26, 1e-3, 0.02).passed);
  EXPECT_FALSE(mean_test(std::vector<double>{1.0}, 1.0, 1e-3).passed);  // one value says nothing
  std::vector<double> with_nan = {1.0, NAN, 2.0};
  const MeanTestResult nan_result = mean_test(with_nan, 1.5, 1e-3);
  EXPECT_FALSE(nan_result.passed);
  EXPECT_NE(nan_result.reason.find("nan"), std::string::npos) << nan_result.reason;
}

// A bias hidden in added noise: values 0.5 too high with a spread of 100 pass a plain t-test at
// 1,000 values (the standard error is about 3); with the variance a right source can have (1),
// the added spread counts no further and the bias fails. Values as noisy as allowed keep the test.
TEST(Statistics, MeanTestCountsTheSpreadOnlyUpToTheVarianceARightSourceCanHave) {
  Pcg32 random(7, stream_of("statistics"));
  std::vector<double> biased_and_noisy, right;
  for (int i = 0; i < 1000; ++i) {
    biased_and_noisy.push_back(0.5 + 100.0 * normal_value(random));
    right.push_back(normal_value(random));
  }
  EXPECT_TRUE(mean_test(biased_and_noisy, 0.0, 1e-3).passed);
  const MeanTestResult capped = mean_test(biased_and_noisy, 0.0, 1e-3, 0.0, 1.0);
  EXPECT_FALSE(capped.passed) << capped.describe();
  EXPECT_NEAR(capped.standard_error, std::sqrt(1.0 / 1000.0), 1e-12);
  EXPECT_TRUE(mean_test(right, 0.0, 1e-3, 0.0, 1.5).passed);  // its variance is under the cap: no change
  EXPECT_EQ(mean_test(right, 0.0, 1e-3, 0.0, 1.5).standard_error, mean_test(right, 0.0, 1e-3).standard_error);
}

TEST(Statistics, MeanTestFalseFailureRateIsItsSignificanceLevel) {
  struct Case {
    const char* what;
    int count;
    bool exponential;  // else normal
  };
  // Normal values at a small count (the t distribution is exact there), and skewed exponential
  // values at 1000 (the central limit theorem's regime, where estimators are tested).
  for (const Case c : {Case{"t-test, 10 normal values", 10, false}, Case{"t-test, 1000 exponential values", 1000, true}})
    for (const double level : {0.05, 0.001}) {
      const int runs = level > 0.01 ? 4000 : 20000;
      int failures = 0;
      for (int run = 0; run < runs; ++run) {
        Pcg32 random(static_cast<std::uint64_t>(run), stream_of(c.what));
        RunningMoments moments;
        for (int i = 0; i < c.count; ++i)
          moments.add(c.exponential ? -std::log(uniform_open(random)) : normal_value(random));
        failures += !mean_test(moments, c.exponential ? 1.0 : 0.0, level).passed;
      }
      expect_rate_near(failures, runs, level, c.what);
    }
}

TEST(Statistics, TwoSampleTestRejectsDifferentMeansAndKeepsItsRate) {
  Pcg32 random(5, stream_of("statistics"));
  RunningMoments a, b;
  for (int i = 0; i < 200; ++i) a.add(normal_value(random));
  for (int i = 0; i < 50; ++i) b.add(3.0 + 3.0 * normal_value(random));  // 7 standard errors apart
  EXPECT_FALSE(two_sample_mean_test(a, b, 1e-3).passed) << two_sample_mean_test(a, b, 1e-3).describe();

  const int runs = 4000;
  int failures = 0;
  for (int run = 0; run < runs; ++run) {
    Pcg32 generator(static_cast<std::uint64_t>(run), stream_of("welch rate"));
    RunningMoments first, second;  // equal means, unequal spreads and sizes
    for (int i = 0; i < 15; ++i) first.add(normal_value(generator));
    for (int i = 0; i < 40; ++i) second.add(4.0 * normal_value(generator));
    failures += !two_sample_mean_test(first, second, 0.05).passed;
  }
  expect_rate_near(failures, runs, 0.05, "Welch t-test");
}

}  // namespace
}  // namespace raylab::testkit
