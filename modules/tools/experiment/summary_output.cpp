#include "tools/experiment/summary_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace beft::experiment {
namespace {

// A number rounded for reading, null for NaN.
nlohmann::json number(double value, int decimals = 3) {
  if (!std::isfinite(value)) return nullptr;
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale;
}

std::string pValue(double p) {
  char text[32];
  std::snprintf(text, sizeof(text), p < 0.001 ? "%.2e" : "%.4f", p);
  return text;
}

std::string fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "-";
  char text[48];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

std::string wilcoxonLine(const ComparisonSummary& c) {
  if (c.time_to_find.n == 0) return "no pair with a difference to test";
  return std::to_string(c.time_to_find.n) + " pairs differ, median A - B " +
         fixed(c.time_to_find_difference_median_s, 1) + " s; Wilcoxon signed-rank W+ = " +
         fixed(c.time_to_find.w_plus, 1) + ", p = " + pValue(c.time_to_find.p) +
         (c.time_to_find.exact ? " (exact)" : " (normal approximation)");
}

double rate(const ConditionSummary& c) { return c.done > 0 ? static_cast<double>(c.successes) / c.done : NAN; }

}  // namespace

void writeSummaryCsv(const Summary& summary, std::ostream& out) {
  out << "condition,episodes,done,failed,missing,successes,success_rate,success_low_95,success_high_95,"
         "time_to_find_q1_s,time_to_find_median_s,time_to_find_q3_s,collisions,episodes_with_collision\n";
  for (const auto& c : summary.conditions)
    out << csvField(c.condition) << "," << c.episodes << "," << c.done << "," << c.failed << "," << c.missing << ","
        << c.successes << "," << csvNumber(rate(c)) << "," << csvNumber(c.success_95.low) << ","
        << csvNumber(c.success_95.high) << "," << csvNumber(c.time_to_find_q1_s) << ","
        << csvNumber(c.time_to_find_median_s) << "," << csvNumber(c.time_to_find_q3_s) << "," << c.collisions << ","
        << c.episodes_with_collision << "\n";
  out << "\ncondition_a,condition_b,pairs,both_succeeded,only_a,only_b,neither,mcnemar_exact_p,"
         "time_to_find_differing_pairs,time_to_find_median_difference_s,wilcoxon_w_plus,wilcoxon_p,wilcoxon_exact\n";
  for (const auto& c : summary.comparisons)
    out << csvField(c.condition_a) << "," << csvField(c.condition_b) << "," << c.pairs << "," << c.both << ","
        << c.only_a << "," << c.only_b << "," << c.neither << "," << pValue(c.mcnemar_p) << "," << c.time_to_find.n
        << "," << csvNumber(c.time_to_find_difference_median_s) << "," << csvNumber(c.time_to_find.w_plus) << ","
        << pValue(c.time_to_find.p) << "," << (c.time_to_find.exact ? 1 : 0) << "\n";
}

nlohmann::json summaryJson(const Summary& summary) {
  nlohmann::json json = {{"conditions", nlohmann::json::array()}, {"comparisons", nlohmann::json::array()}};
  for (const auto& c : summary.conditions) {
    nlohmann::json values = nlohmann::json::object();
    for (const auto& [factor, value] : c.values) values[factor] = value;
    json["conditions"].push_back(
        {{"condition", c.condition}, {"values", values}, {"episodes", c.episodes}, {"done", c.done},
         {"failed", c.failed}, {"missing", c.missing}, {"successes", c.successes}, {"success_rate", number(rate(c))},
         {"success_95", {number(c.success_95.low), number(c.success_95.high)}},
         {"time_to_find_s", {{"q1", number(c.time_to_find_q1_s)}, {"median", number(c.time_to_find_median_s)},
                             {"q3", number(c.time_to_find_q3_s)}}},
         {"collisions", c.collisions}, {"episodes_with_collision", c.episodes_with_collision}});
  }
  for (const auto& c : summary.comparisons)
    json["comparisons"].push_back(
        {{"factor", c.factor}, {"a", c.a}, {"b", c.b}, {"condition_a", c.condition_a}, {"condition_b", c.condition_b},
         {"pairs", c.pairs},
         {"success", {{"both", c.both}, {"only_a", c.only_a}, {"only_b", c.only_b}, {"neither", c.neither},
                      {"mcnemar_exact_p", c.mcnemar_p}}},
         {"time_to_find", {{"pairs", c.time_to_find.n}, {"median_difference_s", number(c.time_to_find_difference_median_s)},
                           {"wilcoxon_w_plus", c.time_to_find.w_plus}, {"wilcoxon_p", c.time_to_find.p},
                           {"exact", c.time_to_find.exact}}}});
  return json;
}

void printSummary(const Summary& summary, std::ostream& out) {
  int width = 9;  // the condition column: as wide as its longest
  for (const auto& c : summary.conditions) width = std::max(width, static_cast<int>(c.condition.size()));
  char line[1024];
  std::snprintf(line, sizeof(line), "%-*s %5s %5s %-18s %-24s %s\n", width, "condition", "done", "fail",
                "success (95% CI)", "time to find q1/med/q3 s", "collisions");
  out << line;
  for (const auto& c : summary.conditions) {
    const std::string success = fixed(100 * rate(c), 0) + "% (" + fixed(100 * c.success_95.low, 0) + "-" +
                                fixed(100 * c.success_95.high, 0) + ")";
    const std::string times = fixed(c.time_to_find_q1_s, 1) + " / " + fixed(c.time_to_find_median_s, 1) + " / " +
                              fixed(c.time_to_find_q3_s, 1);
    std::snprintf(line, sizeof(line), "%-*s %5d %5d %-18s %-24s %d in %d episodes\n", width,
                  c.condition.substr(0, 900).c_str(), c.done, c.failed, success.c_str(), times.c_str(), c.collisions,
                  c.episodes_with_collision);
    out << line;
  }
  for (const auto& c : summary.comparisons)
    out << "\n" << c.condition_a << " vs " << c.condition_b << ": " << c.pairs << " pairs\n"
        << "  success: both " << c.both << ", only A " << c.only_a << ", only B " << c.only_b << ", neither "
        << c.neither << "; McNemar exact p = " << pValue(c.mcnemar_p) << "\n"
        << "  time to find: " << wilcoxonLine(c) << "\n";
}

}  // namespace beft::experiment
