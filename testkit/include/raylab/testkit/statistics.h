// The kit's one statistics module: every Monte Carlo test (the sampling stage's warps, the
// direct-light estimators, the path tracer's furnace scenes and images) decides with these.
//
// A statistical test of a correct program still fails now and then by bad luck: with a fixed
// seed that never changes between runs, but a correct student implementation that draws its
// numbers differently is a fresh draw. So each test below states its false-failure rate: the
// probability that it fails a correct implementation. The grader uses a rate of at most
// 1 in 1,000 per stage (kGraderFalseFailureRate), split over the stage's tests with
// sidak_level(), and tests/test_statistics.cpp measures the rates over many seeds.
//
// Shape learnt from Nori's warptest/chi2test and pbrt-v4's Chi2Test (expected counts from the
// pdf integrated over each cell, low-count cells pooled, a multiple-test correction); the code
// and its special functions are the kit's own (series and continued fractions as in any
// numerical-methods text).
#pragma once

#include <cstddef>
#include <limits>
#include <functional>
#include <string>
#include <vector>

namespace raylab::testkit {

// ---- Rates ---------------------------------------------------------------------------------

// What the grader accepts as the chance of failing a correct stage by bad luck, for all of the
// stage's statistical tests together.
constexpr double kGraderFalseFailureRate = 1e-3;

// The significance level of each of `number_of_tests` independent tests so that the chance
// that ANY of them fails a correct program is `family_rate` (Sidak: 1 - (1 - rate)^(1 / n);
// a little above Bonferroni's rate / n, and exact for independent tests). number_of_tests >= 1.
double sidak_level(double family_rate, int number_of_tests);

// ---- Distributions ---------------------------------------------------------------------------

// The regularized lower incomplete gamma function P(a, x) = gamma(a, x) / Gamma(a), a > 0,
// x >= 0 (series below a + 1, continued fraction above), and its complement Q = 1 - P computed
// without cancellation (so tiny p-values keep their digits).
double regularized_gamma_p(double a, double x);
double regularized_gamma_q(double a, double x);

// The regularized incomplete beta function I_x(a, b), a, b > 0, 0 <= x <= 1 (continued
// fraction, by symmetry on the side where it converges fast).
double regularized_beta(double a, double b, double x);

// Standard normal: P(Z <= z), and its inverse (0 < p < 1; bisection on the CDF to double
// precision, so it is exactly the inverse of normal_cdf).
double normal_cdf(double z);
double normal_quantile(double p);

// Chi-square with `degrees_of_freedom` > 0: P(X <= x), P(X >= x) (the p-value of a statistic
// x, without cancellation), and the inverse of the CDF (0 < p < 1).
double chi_square_cdf(double x, double degrees_of_freedom);
double chi_square_upper_tail(double x, double degrees_of_freedom);
double chi_square_quantile(double p, double degrees_of_freedom);

// Student's t with `degrees_of_freedom` > 0: P(T <= t) through the incomplete beta function,
// and its inverse (0 < p < 1).
double student_t_cdf(double t, double degrees_of_freedom);
double student_t_quantile(double p, double degrees_of_freedom);

// Binomial(n, p): P(K >= k), 0 <= k <= n (1 for k = 0). For a quota test: "at most 95% of the
// pixels may have |z| < 2" is P(K >= observed failures) against the significance level.
double binomial_upper_tail(long long k, long long n, double p);

// ---- Chi-square goodness of fit --------------------------------------------------------------

// Why a chi-square test failed, for a caller that words it itself (the grader, in two languages);
// `reason` words it in English.
enum class ChiSquareFailure {
  none,                         // passed
  invalid_expected,             // an expected count is negative, NaN or infinite
  samples_where_none_expected,  // more than the tolerance fell in cells that expect nothing
  too_few_samples,              // fewer than two cells expect min_expected_count or more
  misfit,                       // p_value < significance_level
};

struct ChiSquareResult {
  bool passed = false;
  double statistic = 0;           // sum over the (pooled) cells of (observed - expected)^2 / expected
  int degrees_of_freedom = 0;     // the number of cells after pooling, minus 1
  double p_value = 0;             // P(chi-square >= statistic) if the samples follow `expected`
  double significance_level = 0;  // rejected when p_value < significance_level
  std::size_t cells = 0;          // cells given
  std::size_t pooled_cells = 0;   // cells whose expected count was below the minimum, merged into one
  // Samples in cells where the expected count is 0: the distribution puts probability where the
  // density says there is none. More than `max_samples_where_none_expected` fails outright.
  double samples_where_none_expected = 0;
  double observed_total = 0, expected_total = 0;
  double min_expected_count = 0;  // the minimum a cell expects before it is pooled
  ChiSquareFailure failure = ChiSquareFailure::none;
  std::string reason;             // why it failed, in words ("" when it passed)
  std::string describe() const;   // one line: statistic, dof, p-value, level, pooling
};

// Pearson's chi-square test of observed cell counts against expected ones (the same cells, the
// same order; expected = sample count x the probability of the cell). Cells with an expected
// count below `min_expected_count` are pooled into one cell (and that cell with the next
// smallest until it reaches the minimum), so that the chi-square approximation holds. Counts in
// cells with expected count 0 are judged apart, as above; their default tolerance, 1e-5 of the
// samples, allows for samples that rounding puts on the wrong side of a boundary.
//
// False-failure rate: `significance_level` (for a correct distribution and at least a few
// hundred samples; the approximation is good once every pooled cell expects >= 5).
// Expected counts summing to something other than the observed total (a pdf that does not
// integrate to 1) are a misfit like any other: the test rejects them when the difference is
// beyond the noise.
ChiSquareResult chi_square_test(const std::vector<double>& observed, const std::vector<double>& expected,
                                double significance_level, double min_expected_count = 5.0,
                                double max_samples_where_none_expected = -1.0 /* -1: 1e-5 of the samples */);

// A grid of cells over the rectangle [u_min, u_max) x [v_min, v_max) of some parameters (say
// z = cos(theta) and phi for directions): counts samples per cell and turns a density over the
// parameters into expected counts. Cell (column, row) is index row * columns + column.
class Histogram2D {
 public:
  Histogram2D(int columns, int rows, double u_min, double u_max, double v_min, double v_max);

  // Counts the sample in its cell; a sample outside the rectangle (or NaN) is counted in
  // outside() instead.
  void add(double u, double v);
  const std::vector<double>& counts() const { return counts_; }
  double outside() const { return outside_; }
  double total() const { return total_; }

  // sample_count x the integral of density(u, v) over each cell, by Gauss-Legendre quadrature
  // (points_per_axis^2 points per cell: exact for polynomials of degree 2 points_per_axis - 1
  // on each axis). The density must be smooth inside each cell: choose the parameters so that
  // its jumps (a hemisphere's rim, a disk's edge) fall on cell borders.
  std::vector<double> expected_counts(const std::function<double(double u, double v)>& density,
                                      double sample_count, int points_per_axis = 6) const;

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  double cell_area() const { return du_ * dv_; }
  double u_min() const { return u_min_; }
  double v_min() const { return v_min_; }
  double cell_width() const { return du_; }
  double cell_height() const { return dv_; }

 private:
  int columns_, rows_;
  double u_min_, v_min_, du_, dv_;
  std::vector<double> counts_;
  double outside_ = 0, total_ = 0;
};

// ---- Means -------------------------------------------------------------------------------------

// Count, mean and variance of a stream of values, in one pass (Welford's update: no
// cancellation when the mean is large against the spread).
class RunningMoments {
 public:
  void add(double value);
  void merge(const RunningMoments& other);  // as if other's values had been added here
  std::size_t count() const { return count_; }
  double mean() const { return mean_; }
  double variance() const;                   // of the values (divides by count - 1); 0 below 2 values
  double standard_error() const;             // of the mean: sqrt(variance / count)

 private:
  std::size_t count_ = 0;
  double mean_ = 0, sum_squared_deviations_ = 0;
};

struct MeanTestResult {
  bool passed = false;
  std::size_t count = 0;
  double mean = 0, expected_mean = 0, standard_error = 0;
  double statistic = 0;           // (mean - expected) / standard error (after the slack, below)
  double degrees_of_freedom = 0;  // of the t distribution; 0 when the normal one was used
  double p_value = 0;             // two-sided
  double significance_level = 0;
  std::string reason;
  std::string describe() const;   // one line: mean +- standard error against the expectation
};

// Is the population mean of `values` equal to `expected_mean`? A two-sided test of the sample
// mean: Student's t with count - 1 degrees of freedom below kNormalFromCount values, the normal
// distribution (a z-test) from there on, where the two differ by less than 1e-4 in the p-value.
// `slack` >= 0 forgives a deviation of that size (a known bias such as float rounding, far
// below the noise you test for): the statistic is (|mean - expected| - slack)+ / standard error.
// Zero spread (every value the same) passes only if |mean - expected| <= slack.
// `max_variance`: the largest variance one value can have when the source is right (an a-priori
// bound): the sample's variance counts no further, so values made noisier than a right source
// can be, to widen the test, do not (a bias hidden in added noise still fails).
//
// False-failure rate: `significance_level` for values from a normal distribution at any count;
// for other distributions the central limit theorem makes it so as the count grows (skewed
// values, say an estimator that is mostly 0 with rare large values, need thousands: the test
// suite measures an exponential's rate at n = 1000 within 20% of the level).
constexpr std::size_t kNormalFromCount = 10000;
MeanTestResult mean_test(const RunningMoments& moments, double expected_mean, double significance_level,
                         double slack = 0.0, double max_variance = std::numeric_limits<double>::infinity());
MeanTestResult mean_test(const std::vector<double>& values, double expected_mean, double significance_level,
                         double slack = 0.0, double max_variance = std::numeric_limits<double>::infinity());

// Do two independent samples have the same population mean? Welch's two-sided t-test (no
// assumption of equal variances; Welch-Satterthwaite degrees of freedom), normal beyond
// kNormalFromCount values in each. False-failure rate: `significance_level`, as for mean_test.
MeanTestResult two_sample_mean_test(const RunningMoments& first, const RunningMoments& second,
                                    double significance_level);

}  // namespace raylab::testkit
