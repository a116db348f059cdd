// The statistics of an experiment's summary. The distributions (normal,
// binomial) are Boost.Math's; what is computed here is only how they are used.
#pragma once

#include <vector>

namespace beft::experiment {

struct Interval {
  double low = 0, high = 0;
};

// The Wilson score interval of a proportion `successes` / `n` (n > 0).
Interval wilsonInterval(int successes, int n, double confidence = 0.95);

// The q-quantile by linear interpolation between order statistics (R's type 7,
// numpy's default); NaN for no values.
double quantile(std::vector<double> values, double q);

// McNemar's exact test on paired successes: `only_a` pairs where only A
// succeeded, `only_b` where only B did; the two-sided p-value (1 with no
// discordant pair).
double mcnemarExactP(int only_a, int only_b);

struct WilcoxonResult {
  int n = 0;           // pairs with a difference other than zero
  double w_plus = 0;   // the sum of the ranks of the positive differences
  double p = 1;        // two-sided
  bool exact = false;  // the exact null distribution (no ties, n <= 30), else normal with continuity correction
};

// The Wilcoxon signed-rank test on paired differences A - B (zeros dropped,
// ties given their mean rank).
WilcoxonResult wilcoxonSignedRank(const std::vector<double>& differences);

}  // namespace beft::experiment
