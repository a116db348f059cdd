#include "planners/bench/bench_datasets.hpp"

#include "lib/scenario/load_scenario.hpp"
#include "planners/movingai.hpp"
#include "planners/octile_search.hpp"
#include "planners/bench/scenario_raster.hpp"
#include "planners/synthetic_maps.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>

namespace beft::planners::bench {

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> filesWithExtension(const std::string& dir, const std::string& extension) {
  std::vector<fs::path> files;
  std::error_code error;
  if (!fs::is_directory(dir, error)) return files;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    if (entry.is_regular_file() && entry.path().extension() == extension) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

GridCell cellOf(Point2 p) { return {static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y))}; }

}  // namespace

std::vector<size_t> spreadIndices(size_t n, size_t count) {
  std::vector<size_t> out;
  if (n == 0 || count == 0) return out;
  if (count >= n) {
    for (size_t i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  for (size_t i = 0; i < count; ++i) out.push_back(count == 1 ? n / 2 : i * (n - 1) / (count - 1));
  return out;
}

std::vector<BenchMap> movingAiMaps(const std::string& dir, int per_map, std::vector<std::string>& notes) {
  std::vector<BenchMap> maps;
  const auto files = filesWithExtension(dir, ".map");
  if (files.empty()) notes.push_back("no MovingAI maps in " + dir);
  for (const auto& file : files) {
    try {
      BenchMap bench{"movingai", file.stem().string(), std::make_shared<PlanningMap>(loadMovingAiMap(file.string()), 0.0), {}};
      const auto all = loadMovingAiScenario(file.string() + ".scen");
      // Group reachable queries by bucket, pick buckets spread over the range,
      // and the middle query of each.
      std::map<int, std::vector<MovingAiQuery>> by_bucket;
      int skipped = 0;
      for (const auto& q : all) {
        if (q.reachable() && !(q.start_x == q.goal_x && q.start_y == q.goal_y)) by_bucket[q.bucket].push_back(q);
        else ++skipped;
      }
      std::vector<int> buckets;
      for (const auto& entry : by_bucket) buckets.push_back(entry.first);
      for (size_t i : spreadIndices(buckets.size(), static_cast<size_t>(per_map))) {
        const auto& group = by_bucket[buckets[i]];
        const MovingAiQuery& q = group[group.size() / 2];
        bench.queries.push_back({cellCentre(q.start_x, q.start_y), cellCentre(q.goal_x, q.goal_y), q.optimal_length,
                                 "bucket " + std::to_string(q.bucket)});
      }
      if (skipped > 0) notes.push_back(bench.name + ": skipped " + std::to_string(skipped) + " unreachable queries");
      maps.push_back(std::move(bench));
    } catch (const std::exception& e) {
      notes.push_back(std::string("skipped: ") + e.what());
    }
  }
  return maps;
}

std::vector<BenchMap> scenarioMaps(const std::string& dir, int per_map, uint64_t seed, std::vector<std::string>& notes) {
  std::vector<BenchMap> maps;
  const auto files = filesWithExtension(dir, ".xml");
  if (files.empty()) notes.push_back("no scenarios in " + dir);
  for (const auto& file : files) {
    try {
      std::ostringstream warnings;
      const ScenarioMap raster = rasterizeScenario(beft::scenario::loadScenario(file.string(), &warnings));
      auto map = std::make_shared<PlanningMap>(raster.grid, raster.robot_radius);
      BenchMap bench{"scenario", file.stem().string(), map, {}};
      const Point2 start = raster.robot_start;
      if (!map->pointFree(start)) {
        notes.push_back(bench.name + ": the robot's start is within its radius of an obstacle; skipped");
        continue;
      }
      // Reachable goals at least 2 m away, sorted by distance; spread picks.
      const auto wavefront = octileDistanceField(map->inflated(), cellOf(start));
      std::vector<std::pair<double, GridCell>> candidates;
      std::mt19937_64 rng(seed);
      std::uniform_int_distribution<int> pick_x(0, map->width() - 1), pick_y(0, map->height() - 1);
      const double min_distance = 2.0 / raster.resolution;
      for (int tries = 0; tries < 20000 && candidates.size() < 400; ++tries) {
        const GridCell c{pick_x(rng), pick_y(rng)};
        const double d = wavefront[map->inflated().index(c.x, c.y)];
        if (std::isfinite(d) && d >= min_distance) candidates.push_back({d, c});
      }
      std::sort(candidates.begin(), candidates.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      for (size_t i : spreadIndices(candidates.size(), static_cast<size_t>(per_map))) {
        const GridCell goal = candidates[i].second;
        const auto best = octileAStar(map->inflated(), cellOf(start), goal);
        // Optimum from the start's cell centre; the start itself is off-centre.
        bench.queries.push_back({start, cellCentre(goal.x, goal.y),
                                 best.cost + distance(start, cellCentre(cellOf(start).x, cellOf(start).y)),
                                 "q" + std::to_string(bench.queries.size())});
      }
      maps.push_back(std::move(bench));
    } catch (const std::exception& e) {
      notes.push_back(std::string("skipped scenario: ") + e.what());
    }
  }
  return maps;
}

std::vector<BenchMap> trapMaps() {
  std::vector<BenchMap> maps;
  for (SyntheticCase& c : syntheticTrapCases()) {
    auto map = std::make_shared<PlanningMap>(std::move(c.map), 0.0);
    BenchMap bench{"trap", c.name, map, {}};
    for (const auto& [start, goal] : c.queries) {
      const auto best = octileAStar(map->inflated(), cellOf(start), cellOf(goal));
      bench.queries.push_back({start, goal, best.cost, "q" + std::to_string(bench.queries.size())});
    }
    maps.push_back(std::move(bench));
  }
  return maps;
}

}  // namespace beft::planners::bench
