// The summary of an experiment: per condition (the factor values other than
// the scene and the seed) the success rate with its Wilson interval, the
// quartiles of time to find and the collisions; and paired comparisons of two
// conditions over the same scenes and seeds (McNemar's exact test on success,
// Wilcoxon's signed-rank test on time to find).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tools/experiment/metrics.hpp"
#include "tools/experiment/statistics.hpp"

namespace beft::experiment {

struct ConditionSummary {
  std::string condition;
  std::vector<std::pair<std::string, std::string>> values;  // its factor values
  int episodes = 0, done = 0, failed = 0, missing = 0;
  int successes = 0;      // done and completed
  Interval success_95;    // of successes / done (0..1 when none done)
  // Of the episodes' median time to find a person, over those that found one.
  double time_to_find_q1_s = 0, time_to_find_median_s = 0, time_to_find_q3_s = 0;
  int collisions = 0, episodes_with_collision = 0;
};

struct ComparisonSummary {
  std::string factor, a, b;                // the factor's two values compared
  std::string condition_a, condition_b;
  int pairs = 0;                           // scenes and seeds with both episodes done
  int both = 0, only_a = 0, only_b = 0, neither = 0;  // successes
  double mcnemar_p = 1;
  WilcoxonResult time_to_find;             // on A - B of the median time to find
  double time_to_find_difference_median_s = 0;
};

struct Summary {
  std::vector<ConditionSummary> conditions;
  std::vector<ComparisonSummary> comparisons;
};

// The experiment's comparisons, or without any: each factor but the seed
// with exactly two values, its first against its second.
std::vector<Comparison> comparisonsOf(const Experiment& experiment);

Summary summarise(const Experiment& experiment, const std::vector<EpisodeResult>& results);

}  // namespace beft::experiment
