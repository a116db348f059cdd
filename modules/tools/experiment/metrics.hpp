// An episode's measures, read from its report.json, and the experiment's
// episodes.csv: one row per episode, its factor values, state and measures.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "tools/experiment/episode_run.hpp"
#include "tools/experiment/experiment.hpp"

namespace beft::experiment {

struct EpisodeMetrics {
  bool completed = false;
  int persons_found = 0, persons_present = 0;
  int false_alarms = 0, falsified = 0, unsettled = 0, collisions = 0;
  double path_length_m = 0, sim_time_s = 0, wall_time_s = 0;
  double heard_error_mean_m = 0;  // NaN: nothing heard
  double time_to_find_first_s = 0, time_to_find_median_s = 0;  // NaN: nobody found
  // SPL over the persons present (report.json's path_efficiency_mean, a person
  // missed counting 0) and the found persons' own values; NaN / none when the
  // report has none (made without the scenario).
  double path_efficiency_mean = 0;
  std::vector<double> path_efficiency;
  std::string end_reason;  // the report's: why the run ended
  std::vector<double> found_at_s;  // when each person found was found (for the time-to-find curves)
};

struct EpisodeResult {
  Episode episode;
  EpisodeState state;
  std::optional<EpisodeMetrics> metrics;  // for a done episode
};

// nullopt if the report cannot be read.
std::optional<EpisodeMetrics> readMetrics(const std::string& report_file);

// The header and rows of episodes.csv; the factor columns are the experiment's.
void writeEpisodesCsv(const Experiment& experiment, const std::vector<EpisodeResult>& results, std::ostream& out);

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text);
// A number with three decimals; "" for NaN.
std::string csvNumber(double value);

}  // namespace beft::experiment
