// The benchmark's maps and queries: MovingAI maps with a stratified sample of
// their scenario queries, the testbed's own scenarios rasterised, and
// synthetic traps.
#pragma once

#include "planners/geometry.hpp"
#include "planners/planning_map.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace beft::planners::bench {

struct BenchQuery {
  Point2 start, goal;      // [cells]
  double optimum = 0;      // octile optimum on the inflated map [cells]
  std::string label;       // e.g. "bucket 40" or "q2"
};

struct BenchMap {
  std::string dataset;     // movingai | scenario | trap
  std::string name;
  std::shared_ptr<const PlanningMap> map;
  std::vector<BenchQuery> queries;
};

// `count` indices spread evenly over [0, n): 0, ..., n - 1 (stratified sample).
std::vector<size_t> spreadIndices(size_t n, size_t count);

// Every DIR/*.map with a .map.scen: `per_map` reachable queries from buckets
// spread evenly over the file's range (point robot). Problems are appended to
// `notes` and the file skipped.
std::vector<BenchMap> movingAiMaps(const std::string& dir, int per_map, std::vector<std::string>& notes);

// Every DIR/*.xml scenario, rasterised, robot radius inflation; queries from
// the robot's start to `per_map` reachable cells spread over the range of
// distances (seeded).
std::vector<BenchMap> scenarioMaps(const std::string& dir, int per_map, uint64_t seed,
                                   std::vector<std::string>& notes);

// The U-trap, the narrow gap and the comb, with their queries.
std::vector<BenchMap> trapMaps();

}  // namespace beft::planners::bench
