#include "raylab/testkit/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace raylab::testkit {
namespace {

constexpr double kEpsilon = 1e-15;
constexpr double kTiny = 1e-300;
constexpr int kMaxIterations = 100000;

// exp(-x) x^a / Gamma(a): the factor in front of both P and Q.
double gamma_front(double a, double x) { return std::exp(-x + a * std::log(x) - std::lgamma(a)); }

double gamma_p_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < kMaxIterations; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::fabs(term) < std::fabs(sum) * kEpsilon) break;
  }
  return sum * gamma_front(a, x);
}

// Q(a, x) by its continued fraction (modified Lentz).
double gamma_q_fraction(double a, double x) {
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < kMaxIterations; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < kEpsilon) break;
  }
  return gamma_front(a, x) * h;
}

// The continued fraction of I_x(a, b) (modified Lentz), converging fast for x < (a+1)/(a+b+2).
double beta_fraction(double a, double b, double x) {
  const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
  double c = 1.0, d = 1.0 - qab * x / qap;
  if (std::fabs(d) < kTiny) d = kTiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m < kMaxIterations; ++m) {
    const int m2 = 2 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < kEpsilon) break;
  }
  return h;
}

// The x with cdf(x) = p for an increasing cdf, by bisection in [low, high] (widened upwards
// until it brackets p).
template <class Cdf>
double invert(const Cdf& cdf, double p, double low, double high) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("a quantile needs 0 < p < 1");
  while (cdf(high) < p && high < 1e300) high *= 2.0;
  for (int i = 0; i < 200 && high - low > 1e-15 * std::max(1.0, std::fabs(high)); ++i) {
    const double middle = 0.5 * (low + high);
    (cdf(middle) < p ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

std::string number(double value) {
  std::ostringstream out;
  out.precision(4);
  out << value;
  return out.str();
}

void check_level(double significance_level) {
  if (!(significance_level > 0.0 && significance_level < 1.0))
    throw std::invalid_argument("a significance level must be in (0, 1)");
}

// Legendre nodes and weights on [-1, 1] (Newton's method on P_n).
void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(n, 0.0);
  weights.assign(n, 0.0);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5)), derivative = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::fabs(step) < 1e-16) break;
    }
    nodes[i] = x;
    weights[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
}

}  // namespace

double sidak_level(double family_rate, int number_of_tests) {
  check_level(family_rate);
  if (number_of_tests < 1) throw std::invalid_argument("sidak_level: at least one test");
  // 1 - (1 - r)^(1/n), without cancellation for small r.
  return -std::expm1(std::log1p(-family_rate) / number_of_tests);
}

double regularized_gamma_p(double a, double x) {
  if (!(a > 0.0) || !(x >= 0.0)) throw std::invalid_argument("regularized_gamma_p: needs a > 0, x >= 0");
  if (x == 0.0) return 0.0;
  return x < a + 1.0 ? gamma_p_series(a, x) : 1.0 - gamma_q_fraction(a, x);
}

double regularized_gamma_q(double a, double x) {
  if (!(a > 0.0) || !(x >= 0.0)) throw std::invalid_argument("regularized_gamma_q: needs a > 0, x >= 0");
  if (x == 0.0) return 1.0;
  if (std::isinf(x)) return 0.0;
  return x < a + 1.0 ? 1.0 - gamma_p_series(a, x) : gamma_q_fraction(a, x);
}

double regularized_beta(double a, double b, double x) {
  if (!(a > 0.0) || !(b > 0.0) || !(x >= 0.0 && x <= 1.0))
    throw std::invalid_argument("regularized_beta: needs a, b > 0 and 0 <= x <= 1");
  if (x == 0.0) return 0.0;
  if (x == 1.0) return 1.0;
  const double front =
      std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_fraction(a, b, x) / a;
  return 1.0 - front * beta_fraction(b, a, 1.0 - x) / b;
}

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

double normal_quantile(double p) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("normal_quantile: needs 0 < p < 1");
  if (p > 0.5) return -normal_quantile(1.0 - p);
  return invert([](double z) { return normal_cdf(z); }, p, -40.0, 0.0);
}

double chi_square_cdf(double x, double degrees_of_freedom) {
  if (!(degrees_of_freedom > 0.0)) throw std::invalid_argument("chi-square: degrees of freedom must be > 0");
  return x <= 0.0 ? 0.0 : regularized_gamma_p(0.5 * degrees_of_freedom, 0.5 * x);
}

double chi_square_upper_tail(double x, double degrees_of_freedom) {
  if (!(degrees_of_freedom > 0.0)) throw std::invalid_argument("chi-square: degrees of freedom must be > 0");
  if (std::isnan(x)) return 0.0;
  return x <= 0.0 ? 1.0 : regularized_gamma_q(0.5 * degrees_of_freedom, 0.5 * x);
}

double chi_square_quantile(double p, double degrees_of_freedom) {
  return invert([&](double x) { return chi_square_cdf(x, degrees_of_freedom); }, p, 0.0,
                std::max(1.0, 2.0 * degrees_of_freedom));
}

double student_t_cdf(double t, double degrees_of_freedom) {
  if (!(degrees_of_freedom > 0.0)) throw std::invalid_argument("student t: degrees of freedom must be > 0");
  if (std::isinf(t)) return t > 0 ? 1.0 : 0.0;
  const double tail = 0.5 * regularized_beta(0.5 * degrees_of_freedom, 0.5,
                                             degrees_of_freedom / (degrees_of_freedom + t * t));
  return t > 0.0 ? 1.0 - tail : tail;
}

double student_t_quantile(double p, double degrees_of_freedom) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("student_t_quantile: needs 0 < p < 1");
  if (p > 0.5) return -student_t_quantile(1.0 - p, degrees_of_freedom);
  // The t <= 0 with P(T <= t) = p (the lower tail keeps its digits for tiny p), by bisection.
  double low = -1.0, high = 0.0;
  while (student_t_cdf(low, degrees_of_freedom) > p) low *= 2.0;
  for (int i = 0; i < 200 && high - low > 1e-15 * std::max(1.0, std::fabs(low)); ++i) {
    const double middle = 0.5 * (low + high);
    (student_t_cdf(middle, degrees_of_freedom) < p ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

double binomial_upper_tail(long long k, long long n, double p) {
  if (n < 0 || k < 0 || k > n || !(p >= 0.0 && p <= 1.0))
    throw std::invalid_argument("binomial_upper_tail: needs 0 <= k <= n and 0 <= p <= 1");
  if (k == 0) return 1.0;
  if (p == 0.0) return 0.0;
  if (p == 1.0) return 1.0;
  return regularized_beta(static_cast<double>(k), static_cast<double>(n - k + 1), p);
}

// ---- Chi-square ------------------------------------------------------------------------------

std::string ChiSquareResult::describe() const {
  std::ostringstream out;
  out << "chi-square " << number(statistic) << " with " << degrees_of_freedom << " degrees of freedom, p = "
      << number(p_value) << " (rejected below " << number(significance_level) << "); " << cells << " cells";
  if (pooled_cells) out << ", " << pooled_cells << " with few expected samples pooled";
  out << "; " << number(observed_total) << " samples, " << number(expected_total) << " expected";
  if (samples_where_none_expected > 0) out << "; " << number(samples_where_none_expected) << " where none were expected";
  return out.str();
}

ChiSquareResult chi_square_test(const std::vector<double>& observed, const std::vector<double>& expected,
                                double significance_level, double min_expected_count,
                                double max_samples_where_none_expected) {
  check_level(significance_level);
  if (observed.size() != expected.size()) throw std::invalid_argument("chi_square_test: one expected count per cell");
  ChiSquareResult result;
  result.significance_level = significance_level;
  result.cells = observed.size();
  result.min_expected_count = min_expected_count;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    if (!(expected[i] >= 0.0) || !std::isfinite(expected[i])) {
      result.failure = ChiSquareFailure::invalid_expected;
      result.reason = "the expected count of cell " + std::to_string(i) + " is " + number(expected[i]) +
                      " (a density must be finite and >= 0)";
      return result;
    }
    result.observed_total += observed[i];
    result.expected_total += expected[i];
  }
  if (max_samples_where_none_expected < 0.0) max_samples_where_none_expected = 1e-5 * result.observed_total;

  // Cells by expected count, smallest first; those expecting nothing are judged apart.
  std::vector<std::size_t> order(observed.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
  double pooled_observed = 0, pooled_expected = 0;
  double statistic = 0;
  int groups = 0;
  for (const std::size_t cell : order) {
    const double e = expected[cell], o = observed[cell];
    if (e == 0.0) {
      result.samples_where_none_expected += o;
      continue;
    }
    if (e < min_expected_count || (pooled_expected > 0.0 && pooled_expected < min_expected_count)) {
      // Too few expected here (or the pool is still short of the minimum: this cell completes it).
      if (e < min_expected_count) ++result.pooled_cells;
      pooled_observed += o;
      pooled_expected += e;
      continue;
    }
    statistic += (o - e) * (o - e) / e;
    ++groups;
  }
  if (pooled_expected > 0.0) {
    statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++groups;
  }
  result.statistic = statistic;
  result.degrees_of_freedom = groups - 1;
  if (result.samples_where_none_expected > max_samples_where_none_expected) {
    result.failure = ChiSquareFailure::samples_where_none_expected;
    result.reason = number(result.samples_where_none_expected) + " samples fell where the density is 0";
    return result;
  }
  if (result.degrees_of_freedom < 1) {
    result.failure = ChiSquareFailure::too_few_samples;
    result.reason = "too few samples for a chi-square test (fewer than two cells expect " + number(min_expected_count) +
                    " or more)";
    return result;
  }
  result.p_value = chi_square_upper_tail(statistic, result.degrees_of_freedom);
  result.passed = result.p_value >= significance_level;
  if (!result.passed) {
    result.failure = ChiSquareFailure::misfit;
    result.reason = "the samples do not follow the density (p = " + number(result.p_value) + " < " +
                    number(significance_level) + ")";
  }
  return result;
}

Histogram2D::Histogram2D(int columns, int rows, double u_min, double u_max, double v_min, double v_max)
    : columns_(columns), rows_(rows), u_min_(u_min), v_min_(v_min), du_((u_max - u_min) / columns),
      dv_((v_max - v_min) / rows) {
  if (columns < 1 || rows < 1 || !(u_max > u_min) || !(v_max > v_min))
    throw std::invalid_argument("Histogram2D: needs at least one cell and a rectangle of positive size");
  counts_.assign(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), 0.0);
}

void Histogram2D::add(double u, double v) {
  total_ += 1.0;
  const double column = std::floor((u - u_min_) / du_), row = std::floor((v - v_min_) / dv_);
  if (!(column >= 0.0 && column < columns_ && row >= 0.0 && row < rows_)) {  // NaN lands here too
    outside_ += 1.0;
    return;
  }
  counts_[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column)] += 1.0;
}

std::vector<double> Histogram2D::expected_counts(const std::function<double(double, double)>& density,
                                                 double sample_count, int points_per_axis) const {
  if (points_per_axis < 1 || points_per_axis > 64) throw std::invalid_argument("expected_counts: 1 to 64 points per axis");
  std::vector<double> nodes, weights;
  gauss_legendre(points_per_axis, nodes, weights);
  std::vector<double> expected(counts_.size(), 0.0);
  for (int row = 0; row < rows_; ++row)
    for (int column = 0; column < columns_; ++column) {
      const double u0 = u_min_ + column * du_, v0 = v_min_ + row * dv_;
      double integral = 0;
      for (int i = 0; i < points_per_axis; ++i)
        for (int j = 0; j < points_per_axis; ++j) {
          const double u = u0 + 0.5 * du_ * (nodes[i] + 1.0), v = v0 + 0.5 * dv_ * (nodes[j] + 1.0);
          integral += weights[i] * weights[j] * density(u, v);
        }
      expected[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column)] =
          sample_count * integral * 0.25 * du_ * dv_;
    }
  return expected;
}

// ---- Means -------------------------------------------------------------------------------------

void RunningMoments::add(double value) {
  ++count_;
  const double delta = value - mean_;
  mean_ += delta / static_cast<double>(count_);
  sum_squared_deviations_ += delta * (value - mean_);
}

void RunningMoments::merge(const RunningMoments& other) {
  if (other.count_ == 0) return;
  if (count_ == 0) {
    *this = other;
    return;
  }
  const double n1 = static_cast<double>(count_), n2 = static_cast<double>(other.count_);
  const double delta = other.mean_ - mean_;
  mean_ += delta * n2 / (n1 + n2);
  sum_squared_deviations_ += other.sum_squared_deviations_ + delta * delta * n1 * n2 / (n1 + n2);
  count_ += other.count_;
}

double RunningMoments::variance() const {
  return count_ < 2 ? 0.0 : sum_squared_deviations_ / static_cast<double>(count_ - 1);
}

double RunningMoments::standard_error() const {
  return count_ == 0 ? 0.0 : std::sqrt(variance() / static_cast<double>(count_));
}

std::string MeanTestResult::describe() const {
  std::ostringstream out;
  out << "mean " << number(mean) << " +- " << number(standard_error) << " (standard error, " << count
      << " values) against " << number(expected_mean) << ": " << (degrees_of_freedom > 0 ? "t = " : "z = ")
      << number(statistic);
  if (degrees_of_freedom > 0) out << " with " << number(degrees_of_freedom) << " degrees of freedom";
  out << ", p = " << number(p_value) << " (rejected below " << number(significance_level) << ")";
  return out.str();
}

namespace {

// Two-sided p-value of a statistic, from t with `dof` (normal when dof is 0).
double two_sided_p(double statistic, double dof) {
  const double magnitude = std::fabs(statistic);
  if (dof > 0.0) return regularized_beta(0.5 * dof, 0.5, dof / (dof + magnitude * magnitude));
  return std::erfc(magnitude / std::sqrt(2.0));
}

MeanTestResult decide(MeanTestResult result, double difference, double dof) {
  if (!std::isfinite(result.mean)) {
    result.reason = "the mean is " + number(result.mean);
    return result;
  }
  if (result.standard_error == 0.0 || !std::isfinite(result.standard_error)) {
    result.passed = std::fabs(difference) == 0.0;
    result.statistic = result.passed ? 0.0 : std::numeric_limits<double>::infinity();
    result.p_value = result.passed ? 1.0 : 0.0;
    if (!result.passed) result.reason = "every value is the same, and differs from the expected mean";
    return result;
  }
  result.statistic = difference / result.standard_error;
  result.degrees_of_freedom = dof;
  result.p_value = two_sided_p(result.statistic, dof);
  result.passed = result.p_value >= result.significance_level;
  if (!result.passed)
    result.reason = "the mean differs from the expected value by " + number(std::fabs(result.statistic)) +
                    " standard errors (p = " + number(result.p_value) + ")";
  return result;
}

}  // namespace

MeanTestResult mean_test(const RunningMoments& moments, double expected_mean, double significance_level, double slack,
                         double max_variance) {
  check_level(significance_level);
  if (!(slack >= 0.0)) throw std::invalid_argument("mean_test: slack must be >= 0");
  if (!(max_variance >= 0.0)) throw std::invalid_argument("mean_test: max_variance must be >= 0");
  MeanTestResult result;
  result.count = moments.count();
  result.mean = moments.mean();
  result.expected_mean = expected_mean;
  result.standard_error = moments.variance() > max_variance
                              ? std::sqrt(max_variance / static_cast<double>(std::max<std::size_t>(moments.count(), 1)))
                              : moments.standard_error();
  result.significance_level = significance_level;
  if (result.count < 2) {
    result.reason = "a mean test needs at least 2 values";
    return result;
  }
  const double deviation = result.mean - expected_mean;
  const double difference = std::copysign(std::max(0.0, std::fabs(deviation) - slack), deviation);
  const double dof = result.count < kNormalFromCount ? static_cast<double>(result.count - 1) : 0.0;
  return decide(result, difference, dof);
}

MeanTestResult mean_test(const std::vector<double>& values, double expected_mean, double significance_level,
                         double slack, double max_variance) {
  RunningMoments moments;
  for (const double value : values) moments.add(value);
  return mean_test(moments, expected_mean, significance_level, slack, max_variance);
}

MeanTestResult two_sample_mean_test(const RunningMoments& first, const RunningMoments& second,
                                    double significance_level) {
  check_level(significance_level);
  MeanTestResult result;
  result.count = first.count() + second.count();
  result.mean = first.mean();
  result.expected_mean = second.mean();
  result.significance_level = significance_level;
  if (first.count() < 2 || second.count() < 2) {
    result.reason = "a two-sample test needs at least 2 values in each sample";
    return result;
  }
  const double v1 = first.variance() / static_cast<double>(first.count());
  const double v2 = second.variance() / static_cast<double>(second.count());
  result.standard_error = std::sqrt(v1 + v2);
  double dof = 0.0;
  if (first.count() < kNormalFromCount || second.count() < kNormalFromCount) {
    const double denominator = v1 * v1 / static_cast<double>(first.count() - 1) +
                               v2 * v2 / static_cast<double>(second.count() - 1);
    dof = denominator > 0.0 ? (v1 + v2) * (v1 + v2) / denominator : 1.0;
  }
  return decide(result, first.mean() - second.mean(), dof);
}

}  // namespace raylab::testkit
