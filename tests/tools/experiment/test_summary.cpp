// An episode's measures from its report.json, the CSV rows, and the summary:
// conditions, their success intervals and a paired comparison.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tools/experiment/metrics.hpp"
#include "tools/experiment/summary.hpp"
#include "tools/experiment/summary_output.hpp"

namespace beft::experiment {
namespace {

namespace fs = std::filesystem;

TEST(ExperimentMetrics, ReadFromTheReport) {
  const fs::path file = fs::temp_directory_path() / ("beft_experiment_report_" + std::to_string(getpid()) + ".json");
  std::ofstream(file) << R"({"completed": false, "persons": 3, "collisions": 1, "path_length_m": 52.25,
    "sim_time_s": 120.5, "wall_time_s": 9.5,
    "victims": [{"found_at_s": 30.0}, {"found_at_s": 10.0}],
    "false_alarms": [{"hypothesis": "h"}], "falsified": [{"object": "r1"}, {"object": "r2"}],
    "heard": [{"error_m": 1.0}, {"error_m": 2.0}], "unsettled": ["car6"], "end_reason": "nothing left, to explore"})";
  const auto m = readMetrics(file.string());
  fs::remove(file);
  ASSERT_TRUE(m);
  EXPECT_FALSE(m->completed);
  EXPECT_EQ(m->persons_found, 2);
  EXPECT_EQ(m->persons_present, 3);
  EXPECT_EQ(m->false_alarms, 1);
  EXPECT_EQ(m->falsified, 2);
  EXPECT_EQ(m->collisions, 1);
  EXPECT_EQ(m->unsettled, 1);
  EXPECT_EQ(m->end_reason, "nothing left, to explore");
  EXPECT_DOUBLE_EQ(m->heard_error_mean_m, 1.5);
  EXPECT_DOUBLE_EQ(m->time_to_find_first_s, 10.0);
  EXPECT_DOUBLE_EQ(m->time_to_find_median_s, 20.0);
  EXPECT_FALSE(readMetrics("/nonexistent/report.json"));
}

// A damaged report (fields of another type, list entries that are no
// objects) reads as what it lacks, never as an exception that would end the
// experiment.
TEST(ExperimentMetrics, AReportOfWrongTypesReadsAsWhatItLacks) {
  const fs::path file = fs::temp_directory_path() / ("beft_experiment_damaged_" + std::to_string(getpid()) + ".json");
  std::ofstream(file) << R"({"completed": "yes", "persons": "three", "collisions": null, "path_length_m": [1],
    "end_reason": 7, "victims": [3, {"found_at_s": "soon"}, {"found_at_s": 8.0, "path_efficiency": 0.5}],
    "heard": [null, {"error_m": 4.0}], "path_efficiency_mean": "high"})";
  std::optional<EpisodeMetrics> m;
  EXPECT_NO_THROW(m = readMetrics(file.string()));
  fs::remove(file);
  ASSERT_TRUE(m);
  EXPECT_FALSE(m->completed);
  EXPECT_EQ(m->persons_present, 0);
  EXPECT_EQ(m->collisions, 0);
  EXPECT_DOUBLE_EQ(m->path_length_m, 0.0);
  EXPECT_EQ(m->end_reason, "");
  EXPECT_EQ(m->persons_found, 3);
  EXPECT_EQ(m->found_at_s, (std::vector<double>{0.0, 0.0, 8.0}));
  EXPECT_EQ(m->path_efficiency, (std::vector<double>{0.5}));
  EXPECT_DOUBLE_EQ(m->heard_error_mean_m, 2.0);
  EXPECT_TRUE(std::isnan(m->path_efficiency_mean));
}

TEST(ExperimentMetrics, CsvFields) {
  EXPECT_EQ(csvField("plain"), "plain");
  EXPECT_EQ(csvField("a, \"b\""), "\"a, \"\"b\"\"\"");
  EXPECT_EQ(csvNumber(1.23456), "1.235");
  EXPECT_EQ(csvNumber(std::nan("")), "");
}

EpisodeResult result(const std::string& scene, const std::string& planner, bool completed, double time_to_find) {
  EpisodeResult r;
  r.episode.values = {{kScene, scene}, {"planner", planner}};
  r.episode.id = scene + "_planner-" + planner;
  r.state.status = Status::done;
  EpisodeMetrics m;
  m.completed = completed;
  m.time_to_find_median_s = time_to_find;
  m.collisions = completed ? 0 : 1;
  r.metrics = m;
  return r;
}

TEST(ExperimentMetrics, EveryRowHasAFieldPerColumn) {
  Experiment x;
  x.factors = {{"planner", {"a"}}};
  EpisodeResult failed = result("s", "a", false, 1);
  failed.metrics.reset();
  failed.state.status = Status::failed;
  failed.state.reason = "beft-run exited with code 2";
  std::vector<EpisodeResult> results = {result("s", "a", true, 12.5), failed};
  results[0].metrics->end_reason = "all found, all settled";
  std::ostringstream csv;
  writeEpisodesCsv(x, results, csv);
  std::istringstream lines(csv.str());
  std::string header, done, not_done;
  std::getline(lines, header);
  std::getline(lines, done);
  std::getline(lines, not_done);
  const auto commas = [](const std::string& line) { return std::count(line.begin(), line.end(), ','); };
  EXPECT_EQ(commas(done), commas(header) + 1);  // the one inside the quoted end_reason
  EXPECT_EQ(commas(not_done), commas(header));
  EXPECT_EQ(not_done, "s_planner-a,s,a,failed,beft-run exited with code 2,,,,,,,,,,,,,,,");
}

// SPL per person: the report's mean over the persons present, and each found
// person's own value; a report made without the scenario has none.
TEST(ExperimentMetrics, PathEfficiencyFromTheReport) {
  const fs::path file = fs::temp_directory_path() / ("beft_experiment_spl_" + std::to_string(getpid()) + ".json");
  std::ofstream(file) << R"({"completed": false, "persons": 3, "path_efficiency_mean": 0.4,
    "victims": [{"found_at_s": 30.0, "path_efficiency": 0.5}, {"found_at_s": 10.0, "path_efficiency": 0.7}]})";
  const auto m = readMetrics(file.string());
  std::ofstream(file) << R"({"completed": true, "persons": 1, "victims": [{"found_at_s": 3.0}]})";
  const auto without = readMetrics(file.string());
  fs::remove(file);
  ASSERT_TRUE(m && without);
  EXPECT_DOUBLE_EQ(m->path_efficiency_mean, 0.4);
  EXPECT_EQ(m->path_efficiency, (std::vector<double>{0.5, 0.7}));
  EXPECT_TRUE(std::isnan(without->path_efficiency_mean));
  EXPECT_TRUE(without->path_efficiency.empty());

  Experiment x;
  EpisodeResult r = result("s", "a", false, 20);
  r.episode.values = {{kScene, "s"}};
  r.metrics = *m;
  std::ostringstream csv;
  writeEpisodesCsv(x, {r}, csv);
  std::istringstream lines(csv.str());
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);
  EXPECT_NE(header.find(",time_to_find_median_s,path_efficiency_mean,end_reason"), std::string::npos) << header;
  EXPECT_NE(row.find(",20.000,0.400,"), std::string::npos) << row;
}

TEST(ExperimentSummary, ConditionsAndAPairedComparison) {
  Experiment x;
  x.factors = {{"planner", {"a", "b"}}};
  std::vector<EpisodeResult> results;
  const double a_times[] = {10, 20, 30, 40, 50}, b_times[] = {12, 25, 33, 48, 61};
  for (int s = 0; s < 5; ++s) {
    results.push_back(result("s" + std::to_string(s), "a", true, a_times[s]));
    results.push_back(result("s" + std::to_string(s), "b", s < 3, b_times[s]));
  }
  results.push_back(result("s9", "a", true, 5));  // no partner: not paired
  const Summary summary = summarise(x, results);
  ASSERT_EQ(summary.conditions.size(), 2u);
  EXPECT_EQ(summary.conditions[0].condition, "planner-a");
  EXPECT_EQ(summary.conditions[0].successes, 6);
  EXPECT_EQ(summary.conditions[1].successes, 3);
  EXPECT_EQ(summary.conditions[1].collisions, 2);
  EXPECT_DOUBLE_EQ(summary.conditions[1].time_to_find_median_s, 33);
  ASSERT_EQ(summary.comparisons.size(), 1u);
  const auto& c = summary.comparisons[0];
  EXPECT_EQ(c.pairs, 5);
  EXPECT_EQ(c.both, 3);
  EXPECT_EQ(c.only_a, 2);
  EXPECT_EQ(c.only_b, 0);
  EXPECT_DOUBLE_EQ(c.mcnemar_p, 0.5);      // 2 * P(X <= 0), X ~ B(2, 1/2)
  EXPECT_DOUBLE_EQ(c.time_to_find.w_plus, 0);
  EXPECT_DOUBLE_EQ(c.time_to_find.p, 2.0 / 32);  // every difference negative: 2 / 2^5
  std::ostringstream csv;
  writeSummaryCsv(summary, csv);
  EXPECT_NE(csv.str().find("planner-a,planner-b,5,3,2,0,0,0.5000,5,"), std::string::npos) << csv.str();
  EXPECT_EQ(summaryJson(summary)["conditions"][0]["success_rate"], 1.0);
}

}  // namespace
}  // namespace beft::experiment
