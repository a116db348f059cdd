#include "planners/bench/bench_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace beft::planners::bench {

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double position = std::clamp(q, 0.0, 1.0) * (values.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(position));
  const size_t above = std::min(below + 1, values.size() - 1);
  const double fraction = position - below;
  // Infinite values (runs that never got there) stay infinite, never NaN.
  if (fraction == 0 || values[above] == values[below]) return values[below];
  return values[below] + fraction * (values[above] - values[below]);
}

double median(std::vector<double> values) { return percentile(std::move(values), 0.5); }

double mean(const std::vector<double>& values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  return std::accumulate(values.begin(), values.end(), 0.0) / values.size();
}

std::vector<Summary> summarize(const std::vector<RunRecord>& runs, bool per_map) {
  std::vector<std::pair<std::string, std::string>> order;
  std::map<std::pair<std::string, std::string>, std::vector<const RunRecord*>> groups;
  for (const RunRecord& run : runs) {
    const auto key = std::make_pair(run.planner, per_map ? run.map : std::string("all"));
    if (groups.find(key) == groups.end()) order.push_back(key);
    groups[key].push_back(&run);
  }
  std::vector<Summary> out;
  for (const auto& key : order) {
    Summary s;
    s.planner = key.first;
    s.map = key.second;
    std::vector<double> ratios, times, turning, clearance;
    for (const RunRecord* run : groups[key]) {
      ++s.runs;
      times.push_back(run->time_ms);
      if (!run->success) continue;
      ++s.successes;
      ratios.push_back(run->ratio);
      turning.push_back(run->turning_deg);
      clearance.push_back(run->clearance);
    }
    s.success_rate = s.runs > 0 ? static_cast<double>(s.successes) / s.runs : 0.0;
    s.ratio_median = median(ratios);
    s.ratio_mean = mean(ratios);
    s.time_median = median(times);
    s.time_p25 = percentile(times, 0.25);
    s.time_p75 = percentile(times, 0.75);
    s.turning_median = median(turning);
    s.clearance_median = median(clearance);
    out.push_back(s);
  }
  return out;
}

}  // namespace beft::planners::bench
