#include "tools/experiment/statistics.hpp"

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace beft::experiment {

Interval wilsonInterval(int successes, int n, double confidence) {
  const boost::math::normal normal;
  const double z = boost::math::quantile(normal, 1 - (1 - confidence) / 2);
  const double p = static_cast<double>(successes) / n, z2 = z * z;
  const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
  const double half = z / (1 + z2 / n) * std::sqrt(p * (1 - p) / n + z2 / (4.0 * n * n));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double position = q * (values.size() - 1);
  const auto below = static_cast<size_t>(std::floor(position));
  const auto above = std::min(below + 1, values.size() - 1);
  return values[below] + (position - below) * (values[above] - values[below]);
}

double mcnemarExactP(int only_a, int only_b) {
  const int n = only_a + only_b;
  if (n == 0) return 1.0;
  const boost::math::binomial_distribution<> binomial(n, 0.5);
  return std::min(1.0, 2 * boost::math::cdf(binomial, std::min(only_a, only_b)));
}

namespace {

// The ranks (1-based, ties their mean) of |d|, in the order of `d`.
std::vector<double> absoluteRanks(const std::vector<double>& d, bool* ties, double* tie_correction) {
  std::vector<size_t> order(d.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return std::abs(d[a]) < std::abs(d[b]); });
  std::vector<double> ranks(d.size());
  *ties = false;
  *tie_correction = 0;
  for (size_t i = 0; i < order.size();) {
    size_t j = i;
    while (j + 1 < order.size() && std::abs(d[order[j + 1]]) == std::abs(d[order[i]])) ++j;
    const double t = static_cast<double>(j - i + 1);
    if (t > 1) *ties = true;
    *tie_correction += t * t * t - t;
    for (size_t k = i; k <= j; ++k) ranks[order[k]] = (i + j) / 2.0 + 1;
    i = j + 1;
  }
  return ranks;
}

// P(W+ <= w) under the null hypothesis, by counting the 2^n sign patterns.
double exactLowerTail(int n, double w) {
  const int most = n * (n + 1) / 2;
  std::vector<double> ways(most + 1, 0.0);
  ways[0] = 1;
  for (int rank = 1; rank <= n; ++rank)
    for (int sum = most; sum >= rank; --sum) ways[sum] += ways[sum - rank];
  double below = 0;
  for (int sum = 0; sum <= std::min(most, static_cast<int>(std::floor(w + 1e-9))); ++sum) below += ways[sum];
  return below / std::pow(2.0, n);
}

}  // namespace

WilcoxonResult wilcoxonSignedRank(const std::vector<double>& differences) {
  std::vector<double> d;
  for (const double x : differences)
    if (x != 0 && std::isfinite(x)) d.push_back(x);
  WilcoxonResult result;
  result.n = static_cast<int>(d.size());
  if (d.empty()) return result;
  bool ties = false;
  double tie_correction = 0;
  const auto ranks = absoluteRanks(d, &ties, &tie_correction);
  for (size_t i = 0; i < d.size(); ++i)
    if (d[i] > 0) result.w_plus += ranks[i];
  const double n = result.n, mean = n * (n + 1) / 4;
  const double smaller = std::min(result.w_plus, n * (n + 1) / 2 - result.w_plus);
  result.exact = !ties && result.n <= 30;
  if (result.exact) {
    result.p = std::min(1.0, 2 * exactLowerTail(result.n, smaller));
    return result;
  }
  const double sd = std::sqrt(n * (n + 1) * (2 * n + 1) / 24 - tie_correction / 48);
  const double z = (sd > 0) ? std::max(0.0, std::abs(result.w_plus - mean) - 0.5) / sd : 0;
  result.p = std::min(1.0, 2 * boost::math::cdf(boost::math::complement(boost::math::normal(), z)));
  return result;
}

}  // namespace beft::experiment
