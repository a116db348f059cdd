#include "tools/experiment/summary.hpp"

#include <cmath>
#include <limits>
#include <map>

namespace beft::experiment {
namespace {

bool succeeded(const EpisodeResult& r) { return r.metrics && r.metrics->completed; }

double timeToFind(const EpisodeResult& r) {
  return r.metrics ? r.metrics->time_to_find_median_s : std::numeric_limits<double>::quiet_NaN();
}

void count(ConditionSummary& s, const EpisodeResult& r, std::vector<double>& times) {
  ++s.episodes;
  if (r.state.status == Status::failed) ++s.failed;
  if (r.state.status == Status::missing || (r.state.status == Status::done && !r.metrics)) ++s.missing;
  if (!r.metrics) return;
  ++s.done;
  if (succeeded(r)) ++s.successes;
  s.collisions += r.metrics->collisions;
  if (r.metrics->collisions > 0) ++s.episodes_with_collision;
  if (std::isfinite(timeToFind(r))) times.push_back(timeToFind(r));
}

std::vector<ConditionSummary> summariseConditions(const std::vector<EpisodeResult>& results) {
  std::vector<ConditionSummary> conditions;
  std::map<std::string, size_t> index;
  std::vector<std::vector<double>> times;
  for (const auto& r : results) {
    const std::string condition = r.episode.condition();
    if (index.emplace(condition, conditions.size()).second) {
      conditions.emplace_back();
      conditions.back().condition = condition;
      for (const auto& [factor, value] : r.episode.values)
        if (factor != kScene && factor != kSeed) conditions.back().values.emplace_back(factor, value);
      times.emplace_back();
    }
    count(conditions[index[condition]], r, times[index[condition]]);
  }
  for (size_t i = 0; i < conditions.size(); ++i) {
    auto& s = conditions[i];
    s.success_95 = s.done > 0 ? wilsonInterval(s.successes, s.done) : Interval{0, 1};
    s.time_to_find_q1_s = quantile(times[i], 0.25);
    s.time_to_find_median_s = quantile(times[i], 0.5);
    s.time_to_find_q3_s = quantile(times[i], 0.75);
  }
  return conditions;
}

std::string partnerCondition(const Episode& episode, const std::string& factor, const std::string& value) {
  Episode partner = episode;
  for (auto& [name, v] : partner.values)
    if (name == factor) v = value;
  return partner.condition();
}

void addPair(ComparisonSummary& c, const EpisodeResult& a, const EpisodeResult& b, std::vector<double>& differences) {
  ++c.pairs;
  const bool sa = succeeded(a), sb = succeeded(b);
  (sa && sb ? c.both : sa ? c.only_a : sb ? c.only_b : c.neither)++;
  const double difference = timeToFind(a) - timeToFind(b);
  if (std::isfinite(difference)) differences.push_back(difference);
}

// One comparison per condition with the factor's value a that has a partner with b.
void compare(const Comparison& comparison, const std::vector<EpisodeResult>& results, std::vector<ComparisonSummary>& out) {
  std::map<std::pair<std::string, std::string>, const EpisodeResult*> by_condition_and_pairing;
  for (const auto& r : results)
    if (r.metrics) by_condition_and_pairing[{r.episode.condition(), r.episode.pairing()}] = &r;
  std::map<std::string, ComparisonSummary> found;
  std::map<std::string, std::vector<double>> differences;
  for (const auto& r : results) {
    const std::string* value = r.episode.value(comparison.factor);
    if (!r.metrics || value == nullptr || *value != comparison.a) continue;
    const std::string partner = partnerCondition(r.episode, comparison.factor, comparison.b);
    const auto b = by_condition_and_pairing.find({partner, r.episode.pairing()});
    auto& c = found[r.episode.condition()];
    c.factor = comparison.factor;
    c.a = comparison.a;
    c.b = comparison.b;
    c.condition_a = r.episode.condition();
    c.condition_b = partner;
    if (b != by_condition_and_pairing.end()) addPair(c, r, *b->second, differences[c.condition_a]);
  }
  for (auto& [condition, c] : found) {
    c.mcnemar_p = mcnemarExactP(c.only_a, c.only_b);
    c.time_to_find = wilcoxonSignedRank(differences[condition]);
    c.time_to_find_difference_median_s = quantile(differences[condition], 0.5);
    out.push_back(c);
  }
}

}  // namespace

std::vector<Comparison> comparisonsOf(const Experiment& experiment) {
  if (!experiment.comparisons.empty()) return experiment.comparisons;
  std::vector<Comparison> comparisons;
  for (const auto& factor : experiment.factors)
    if (factor.name != kSeed && factor.values.size() == 2)
      comparisons.push_back({factor.name, factor.values[0], factor.values[1]});
  return comparisons;
}

Summary summarise(const Experiment& experiment, const std::vector<EpisodeResult>& results) {
  Summary summary;
  summary.conditions = summariseConditions(results);
  for (const auto& comparison : comparisonsOf(experiment)) compare(comparison, results, summary.comparisons);
  return summary;
}

}  // namespace beft::experiment
