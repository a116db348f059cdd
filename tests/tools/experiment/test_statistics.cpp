// The statistics against values published or computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "tools/experiment/statistics.hpp"

namespace beft::experiment {
namespace {

TEST(ExperimentStatistics, WilsonIntervalOfEightInTen) {
  // Wilson (1927); 8/10 at 95 %: [0.4902, 0.9433] (e.g. Newcombe 1998, method 3).
  const Interval i = wilsonInterval(8, 10);
  EXPECT_NEAR(i.low, 0.490162, 1e-5);
  EXPECT_NEAR(i.high, 0.943318, 1e-5);
  const Interval all = wilsonInterval(20, 20);  // all succeeded: [0.8389, 1]
  EXPECT_NEAR(all.low, 0.838875, 1e-5);
  EXPECT_DOUBLE_EQ(all.high, 1.0);
  const Interval none = wilsonInterval(0, 4);
  EXPECT_DOUBLE_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, 0.489891, 1e-5);
}

TEST(ExperimentStatistics, QuantilesInterpolateLikeRsType7) {
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.25), 1.75);
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.75), 3.25);
  EXPECT_DOUBLE_EQ(quantile({7}, 0.75), 7);
  EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
}

TEST(ExperimentStatistics, McNemarExactP) {
  // 1 pair only A, 8 only B: 2 * P(X <= 1), X ~ B(9, 1/2) = 2 * 10 / 512.
  EXPECT_NEAR(mcnemarExactP(1, 8), 20.0 / 512, 1e-12);
  EXPECT_NEAR(mcnemarExactP(10, 2), 2 * (1 + 12 + 66) / 4096.0, 1e-12);
  EXPECT_DOUBLE_EQ(mcnemarExactP(5, 5), 1.0);
  EXPECT_DOUBLE_EQ(mcnemarExactP(0, 0), 1.0);
}

TEST(ExperimentStatistics, WilcoxonSignedRankExact) {
  // Hollander & Wolfe's depression scale (R's ?wilcox.test): x - y; V = 40, p = 0.03906.
  const std::vector<double> x = {1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
  const std::vector<double> y = {0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
  std::vector<double> d;
  for (size_t i = 0; i < x.size(); ++i) d.push_back(x[i] - y[i]);
  const auto w = wilcoxonSignedRank(d);
  EXPECT_EQ(w.n, 9);
  EXPECT_DOUBLE_EQ(w.w_plus, 40);
  EXPECT_TRUE(w.exact);
  EXPECT_NEAR(w.p, 20.0 / 512, 1e-12);  // 0.0390625
}

TEST(ExperimentStatistics, WilcoxonSignedRankWithTiesAndZeros) {
  // |d| ranks 1.5 1.5 4 4 4 6 7 8, W+ = 34.5; variance 8*9*17/24 - (6 + 24)/48;
  // z = (34.5 - 18 - 0.5) / sd = 2.2543, p = erfc(z / sqrt 2) = 0.024177.
  const auto w = wilcoxonSignedRank({1, -1, 2, 2, 0, 2, 3, 4, 5, 0});
  EXPECT_EQ(w.n, 8);
  EXPECT_DOUBLE_EQ(w.w_plus, 34.5);
  EXPECT_FALSE(w.exact);
  EXPECT_NEAR(w.p, 0.0241771, 1e-6);
  EXPECT_DOUBLE_EQ(wilcoxonSignedRank({0, 0}).p, 1.0);
}

}  // namespace
}  // namespace beft::experiment
